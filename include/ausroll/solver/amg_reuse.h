/**
 * @file amg_reuse.h
 * When the iterative solver builds its AMG preconditioner anew (`Solver/Linear solver/AMG reuse`).
 */
#pragma once

namespace ausroll::solver
{
  /**
   * The decision of LinearSolver to keep or rebuild its AMG set-up. Without reuse every solve
   * sets up a new AMG. With reuse (`AMG reuse = true`) a set-up is kept over the following
   * solves (Newton iterations, load steps) until
   *  - the matrix pattern changes (mesh change: invalidate()),
   *  - a solve with the kept set-up fails (invalidate(); the solver repeats it with a new one),
   *  - a solve needs more than `AMG rebuild factor` times the Krylov iterations per decade of
   *    residual reduction of the first solve with the set-up (the tangent has moved away from
   *    the matrix the hierarchy was built from: contact status changes, plastic zones).
   * Iterations per decade, k / log10(|b| / |b - A x|), and not iterations, so that solves to
   * different tolerances (Krylov tolerance = adaptive) compare. A solve of fewer than
   * minimum_judged_iterations iterations is not judged (it neither sets the reference nor
   * triggers a rebuild): its count is too coarse for a rate (1 to 9), and the first iterations of
   * GMRES reduce the residual faster than the later ones (3D gear, level 2: 4 iterations for
   * 2 decades in the first solve of a step, 28 for 3 decades in the third); such a solve is also
   * too cheap for a rebuild to pay (a set-up costs about 20 Krylov iterations there).
   */
  class AmgReuse
  {
  public:
    /** @p reuse: `AMG reuse`; @p rebuild_factor: `AMG rebuild factor` (>= 1). */
    AmgReuse(bool reuse, double rebuild_factor);

    /** Whether the next solve needs a new set-up. */
    bool needs_setup() const { return !reuse || !valid; }

    /** A new set-up was built: the next converged solve is its reference. */
    void set_up();

    /** The set-up must not be used again (mesh change, failed solve). */
    void invalidate() { valid = false; }

    /**
     * A converged solve with the current set-up took @p iterations Krylov iterations and reduced
     * the residual by @p reduction = |b - A x| / |b|: the first one after set_up() becomes the
     * reference, a later one slower than the rebuild factor times it invalidates the set-up.
     * A solve of fewer than minimum_judged_iterations iterations or no reduction (b = 0) says
     * nothing and is ignored.
     */
    void solved(unsigned int iterations, double reduction);

    /** Solves with fewer Krylov iterations are not judged (see the class comment). */
    static constexpr unsigned int minimum_judged_iterations = 10;

    /** Krylov iterations per decade of residual reduction (0 if nothing was reduced). */
    static double iterations_per_decade(unsigned int iterations, double reduction);

    /** The reference rate of the current set-up (0 before its first converged solve). */
    double reference_rate() const { return reference; }

  private:
    bool   reuse;
    double rebuild_factor;
    bool   valid = false;
    double reference = 0.;
  };
} // namespace ausroll::solver
