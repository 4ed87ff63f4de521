/**
 * @file contact_operator.h
 * Node-to-segment contact of workpiece boundary nodes with rigid dies, adapted from Okamoto's
 * contact element as used in NOFEAP: statuses open / stick / slip, turned into constraints
 * and friction forces; reactions recovered from the residual.
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/contact/nodal_row_transform.h>
#include <ausroll/contact/rigid_die.h>
#include <ausroll/contact/tangent/contact_tangent_term.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ausroll::contact
{
  /** Contact status of a node. */
  enum class ContactStatus
  {
    open = 0,  ///< no constraint
    stick = 1, ///< all displacement components follow the die point where the node stuck
    slip = 2   ///< normal gap zero, tangential force of the friction law opposing the slip
  };

  /**
   * Contact between the workpiece and the rigid dies of subsection `Contact`.
   *
   * Candidates are the support points of the displacement element on the workpiece boundaries
   * listed in each die's `Candidate boundaries`. Every Newton iterate, each node is projected onto
   * the dies (closest point, signed gap, normal, tangent, die coordinate s). Closed nodes become
   * inhomogeneous constraints on the Newton increment:
   *  - stick: delta u = x_die(P, t) - x, P being the die point (die coordinates) where the node
   * stuck;
   *  - slip:  n . delta u = -gap, with the friction force T(R_n) of the die's FrictionLaw
   *    (Coulomb mu R_n, Tresca m k A, ...) opposing the slip added to the tangential equation
   *    through a NodalRowTransform (consistent linearisation).
   * The contact force on a node is its entry of the residual f_int - f_ext (the equilibrium
   * equations of constrained DoFs are not solved, their residual is the reaction); R_n = n.R >= 0
   * in compression, R_t = t.R.
   *
   * The criteria for status changes are here (penetration closes a node, tension R_n < 0 opens
   * it, |R_t| > T(R_n) makes it slip, slip reversal makes it stick; events interpolated over a
   * step); when they are applied is the business of the StatusStrategy of `Contact/Strategy`
   * (contact_strategy.h), which drives this object through the ContactStatusSet interface.
   *
   * Works on the locally relevant nodes of each MPI rank; decisions depend only on ghosted data,
   * so ranks sharing a node take the same decision.
   */
  template <int dim>
  class ContactOperator : public ContactStatusSet
  {
  public:
    /** Dies, friction laws and status-rule settings from @p parameters; @p friction: what the
        friction laws need from the workpiece (the shear yield stress of the shear laws). */
    explicit ContactOperator(const ContactParameters &parameters,
                             const FrictionContext   &friction = FrictionContext());

    /** True if at least one die is defined. */
    bool active() const { return !dies.empty(); }

    /**
     * Collect the candidate nodes of @p dof_handler and their tributary areas
     * (integral of the nodal shape function over the candidate boundary, times
     * @p volume_factor(x): 2 pi r for axisymmetric models). @p length_scale sets the gap tolerance.
     * Statuses of nodes that existed before (same DoF index) are lost: call after every mesh change
     * and before the first step.
     */
    void setup(const dealii::DoFHandler<dim>                           &dof_handler,
               const dealii::Mapping<dim>                              &mapping,
               const std::function<double(const dealii::Point<dim> &)> &volume_factor,
               const double                                             length_scale);

    /**
     * The committed state of every closed node of all ranks (reference position, status, stick
     * point, slip direction, gap, forces), to carry statuses over a mesh change or into a
     * checkpoint. Same result on all ranks.
     */
    std::vector<double> pack_state() const;

    /**
     * Restore statuses saved by pack_state() on the nodes of the current mesh (matched by reference
     * position). Nodes that are new (mesh refinement) and touch a die are closed.
     */
    void unpack_state(const std::vector<double> &state);

    /**
     * Plausibility of the dies before a run (call after setup()): throws InputError naming the die
     * if it has no candidate nodes, if the undeformed workpiece starts deep inside it (more than
     * 5 % of the workpiece size: usually a flipped Normal or Material inside), overlaps it by
     * more than a tenth of the smallest cell (the first step cannot push the nodes out), or if it
     * never comes
     * within a quarter of the workpiece size of the undeformed workpiece at any of @p times.
     * @p workpiece_size is the diameter of the workpiece's bounding box.
     */
    void check_dies(const std::vector<double> &times, const double workpiece_size) const;

    /** Distance from @p x to the nearest die (|gap|) at time @p t (infinite if none in range). */
    double distance_to_dies(const dealii::Point<dim> &x, const double t) const;

    /** Time of the current iterate (die poses). */
    void set_time(const double t) override { time = t; }

    /**
     * Project all nodes at displacement @p u (ghosted). With @p allow_closing, open nodes that
     * penetrate a die close (stick, or slip if frictionless); with @p only_unchanged_nodes only
     * those that have not changed status in this step (nested active set: a node opened in this
     * step closes again only at a converged state). Returns the number of closed nodes.
     */
    unsigned int update_geometry(const dealii::TrilinosWrappers::MPI::Vector &u,
                                 const bool                                   allow_closing,
                                 const bool only_unchanged_nodes = false) override;

    /**
     * Add the constraints of the closed nodes to @p constraints (which may already hold Dirichlet
     * lines: components constrained already are skipped). Returns the largest constraint violation
     * (|gap| of slipping nodes, distance to the stick point of sticking nodes) over local nodes.
     */
    double add_constraints(const dealii::TrilinosWrappers::MPI::Vector &u,
                           dealii::AffineConstraints<double>           &constraints) const;

    /** Friction row transforms of the slipping nodes (recomputed by update_geometry()). */
    const RowTransforms<dim> &row_transforms() const { return transforms; }

    /**
     * The contact Newton terms beyond the assembled tangent (contact/tangent/: the slip
     * direction, the curvature if `Contact/Curvature tangent`), built once from the parameters
     * and set up on the DoFs by setup(): add each to every assembled matrix.
     */
    const std::vector<std::unique_ptr<ContactTangentTerm<dim>>> &tangent_terms() const
    {
      return tangents;
    }

    /** A locally owned slipping node whose slip direction follows its slip (3D: the slip since
        its slip started is longer than the slip length, update_geometry()): what the slip
        direction tangent (tangent/slip_direction_tangent.h) reads. */
    struct FollowedSlip
    {
      std::array<dealii::types::global_dof_index, dim> dofs;      ///< DoFs by component
      dealii::Tensor<1, dim>                           normal;    ///< die normal
      dealii::Tensor<1, dim>                           direction; ///< unit slip direction d
      double slip = 0.;       ///< |s|, the slip since the slip started
      double slip_limit = 0.; ///< T(R_n) at the normal force of the last compute_reactions()
    };

    /** The slipping nodes whose direction follows the slip (2D: none). */
    std::vector<FollowedSlip> followed_slips() const;

    /** Store the nodal forces R = r(node) from the residual @p residual (ghosted). */
    void compute_reactions(const dealii::TrilinosWrappers::MPI::Vector &residual);

    /** Accept the current statuses and geometry as the state at the end of a converged step
        (@p new_step false: a re-equilibration at the same time, which keeps the record of the
        nodes that closed in the last step). */
    void commit(const bool new_step = true);

    /** Number of dies (`Contact/Number of dies`). */
    unsigned int n_dies() const { return dies.size(); }

    /** Die @p k (name, pose, motion, friction law). */
    const RigidDie<dim> &die(const unsigned int k) const { return *dies[k]; }

    /** Let workpiece boundary @p id touch die @p k too (`Contact/Penetrating boundaries = add`);
        the nodes are set up again by the next setup(). */
    void add_candidate_boundary(const unsigned int k, const unsigned int id)
    {
      dies[k]->add_candidate(id);
    }

    /** The contact of one die at the current state, over all ranks (io::postprocess::DieForces
        makes the history columns of it). */
    struct DieContact
    {
      dealii::Tensor<1, dim> force; ///< force of the die on the workpiece
      /** Moment of these nodal forces about the die's reference point (the die centre of a
          rolling die), N mm; 2D: only the z component. */
      dealii::Tensor<1, 3> moment;
      unsigned int         n_stick = 0, n_slip = 0; ///< sticking / slipping nodes
      /** Extent of the closed nodes' die coordinate s (along the die surface); 0 if none. */
      double contact_length = 0.;
      /** Extent of the closed nodes' current positions along the die-frame x axis (for a die
          pressed along y the contact width); 0 if none. */
      double contact_width = 0.;
    };

    /** The contact of die @p k at the current iterate (collective: call on all ranks). */
    DieContact die_contact(const unsigned int k) const;

    /** A closed contact node as the heat equation sees it (ContactOperator::heat_contacts()). */
    struct HeatContact
    {
      dealii::types::global_dof_index dof = 0;   ///< its displacement DoF of component x
      double                          area = 0.; ///< tributary area (as the contact forces)
      unsigned int                    die = 0;   ///< the die it touches
      /** Frictional work of the step, |R_t| times the slip relative to the die (N mm): nonzero
          for a node that slipped and was closed on the same die at the last commit. */
      double friction_work = 0.;
    };

    /** The locally owned closed nodes of the current (converged, not yet committed) state. */
    std::vector<HeatContact> heat_contacts() const;

    /** Write `contact` CSV (one row per candidate node that is closed or within 1 element of a
     * die). */
    void write_csv(const std::string &filename, const MPI_Comm comm) const;

    /**
     * Nodal fields for VTU output on the DoFs of the displacement field: @p pressure_traction
     * (x: contact pressure p_n, y: tangential traction t_t) and @p status_gap (x: status 0/1/2,
     * y: gap). Vectors must be sized with the locally owned DoFs.
     */
    void fill_output_vectors(dealii::TrilinosWrappers::MPI::Vector &pressure_traction,
                             dealii::TrilinosWrappers::MPI::Vector &status_gap) const;

    /** Nodes whose status differs from the committed one (global): the status changes of the
        step being solved, for the step-size control (`Loading/Step control`). */
    unsigned int n_changed_statuses() const;

    /** Numbers of sticking and of slipping nodes (global, all dies), for the status line. */
    std::pair<unsigned int, unsigned int> n_stick_slip() const;

  private:
    /** @name ContactStatusSet: the status rules, applied by the StatusStrategy of
        `Contact/Strategy` (contact_strategy.h), which alone calls them. */
    //@{
    /**
     * A new displacement iterate begins (after a Newton update): statuses changed at the previous
     * iterate may be judged again by their reactions. Within one iterate a node changes its status
     * at most once: the reaction of a node that was just closed, opened or switched between stick
     * and slip belongs to the old constraint and says nothing about the new one until the
     * equations have been solved with it.
     */
    void start_iterate() override;

    /** Nested active set: a node changed at an iterate is judged again only at the next one. */
    void hold_changed_nodes(const bool hold) override { hold_changed = hold; }

    /**
     * Nested active set: project all nodes at @p u and close the open nodes that penetrate a die.
     * Returns the number of nodes closed (global).
     */
    unsigned int close_penetrating_nodes(const dealii::TrilinosWrappers::MPI::Vector &u) override;

    /**
     * Active set: change statuses by the force criteria (tension opens, |R_t| > mu R_n slips,
     * reversed slip sticks). Call after compute_reactions(). Returns the number of changes over
     * all ranks.
     */
    unsigned int update_statuses(const unsigned int change_limit) override;

    /**
     * Load-increment ratio: the fraction alpha in [0, 1] of the current step at which the first
     * node changes status, by linear interpolation between the committed state and the current
     * iterate (NOFEAP Appendix A). 1 if no node changes. Same value on all ranks.
     */
    double event_ratio() const override;

    /**
     * Load-increment ratio: switch the status of every node whose event lies at or before
     * @p alpha_limit (fraction of the current step). Returns the number of switched nodes (global).
     */
    unsigned int apply_events(const double alpha_limit) override;

    /** Close the open nodes whose gap is zero (within round-off) at the current geometry.
        Returns the number of nodes closed (global). */
    unsigned int close_touching_nodes() override;

    /** Make the current statuses the statuses at the start of the step (status changes at the
        start of a load-increment-ratio step); gaps and forces of the committed state are kept. */
    void promote_statuses() override;

    /** Return to the committed statuses (step cut back). */
    void reset() override;

    /** Nodes that closed in the last converged step and stick (with a tangential reaction)
        slip from the start of the step instead. Returns their number (global). */
    unsigned int release_fresh_sticks() override;
    //@}

  private:
    /**
     * The status of a node and what goes with it: once as committed (end of the last converged
     * step), once as current (the iterate being solved). Commit copies current to committed,
     * a cutback copies it back.
     */
    struct NodeState
    {
      ContactStatus      status = ContactStatus::open;
      int                die = -1; ///< die in contact, or closest die (-1: none in range)
      dealii::Point<dim> stick;    ///< die point of a sticking node (die coordinates)
      /**
       * Slip direction d of a slipping node (unit, components along the die tangents t_a; the
       * friction force is -T(R_n) d): 2D +1/-1 along the die tangent; 3D any direction of the
       * tangent plane (isotropic friction cone). Zero if unknown.
       */
      std::array<double, dim - 1> direction{};

      double s = 0.; ///< die coordinate (2D arc length, 3D the first
                     ///< surface coordinate): committed, at the converged
                     ///< geometry; current, where the current slip started
      /** 3D: die point (die coordinates) where the current slip started (committed: of the
          converged geometry). */
      dealii::Point<dim>          start;
      double                      Rn = 0.; ///< normal contact force (compression positive)
      std::array<double, dim - 1> Rt{};    ///< tangential contact force, components along t_a
    };

    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs; ///< DoFs by component
      dealii::Point<dim>                               X;    ///< reference position
      bool                                             owned = false;
      double                                           area = 0.; ///< tributary area
      std::vector<unsigned int>                        dies;      ///< candidate dies

      NodeState committed;                   ///< end of the last converged step
      NodeState current;                     ///< current iterate
      double    committed_gap = 0.;          ///< gap at the last commit
      bool      committed_gap_valid = false; ///< the node was within a die's search distance

      // geometry and forces of the current iterate
      DieProjection<dim>     projection;  ///< projection on die `current.die`
      dealii::Point<dim>     x;           ///< current position
      dealii::Tensor<1, dim> R;           ///< nodal contact force (residual)
      unsigned int           changes = 0; ///< status changes in the current step
      /** Components already constrained (Dirichlet, symmetry) when the contact constraints were
          added: 3D leaves their residual out of the tangential force (a symmetry-plane reaction
          is no friction). */
      mutable std::array<bool, dim> fixed{};
      /** 3D: the slip direction of the last converged step, taken at the next projection. */
      std::array<double, dim - 1> next_direction{};
      bool                        direction_pending = false;
      bool fresh = false; ///< status changed at the current iterate (reaction not yet meaningful)
      /** The committed status is closed, the one before the last commit was open. */
      bool closed_in_last_step = false;
      /** 3D: the slip direction turned by more than direction_tolerance at the last projection
          (update_geometry()): at a converged state, the residual was not of this direction. */
      bool turned = false;
      /** 3D: |s| at the last projection if the direction follows the slip (> slip_length), else
          0 (the direction is held and has no derivative). */
      double followed_slip = 0.;
      /** 3D, nested active set: the direction follows the slip at every iterate (with its
          derivative) for the rest of the step, since it turned at a converged state. */
      bool follow = false;
    };

    /** A status change of a node: at which fraction of the step, to which status. */
    struct Event
    {
      double        alpha = std::numeric_limits<double>::infinity();
      ContactStatus target = ContactStatus::open;
    };

    /** The next status change of node @p n (linear interpolation over the step). */
    Event node_event(const Node &n) const;

    /** Force of the die on node @p n: normal part from the residual, tangential part from the
        residual (stick) or the friction law (slip). */
    dealii::Tensor<1, dim> contact_force(const Node &n) const;

    /** Status of node @p n when it closes on its die (slip if frictionless, else stick). */
    ContactStatus closing_status(const Node &n) const;

    /** Switch node @p n to @p status at the current iterate. */
    void switch_status(Node &n, const ContactStatus status);

    /**
     * Slip of node @p n since its current slip started, along its slip direction (2D: the signed
     * arc length sign (s - s_start); 3D: d . the tangential part of the die-frame displacement of
     * the projection). Negative: the slip has reversed.
     */
    double slip_along_direction(const Node &n) const;

    /** 3D: the tangential components (along the current tangents) of the slip of node @p n since
        its current slip started (die-relative, rotated to the global frame). */
    std::array<double, dim - 1> slip_increment(const Node &n) const;

    /** 3D: take a pending direction of the last step; with @p follow_slip, d = the direction of
        the slip of node @p n since its current slip started, if that slip is longer than
        slip_length. Returns the turn of d (largest change of a component). */
    double update_slip_direction(Node &n, const bool follow_slip) const;

    /** The slip direction vector d = sum_a d_a t_a of node @p n (global). */
    dealii::Tensor<1, dim> slip_vector(const Node &n) const;

    /** Gap of the global point @p x to die @p k at time @p t without search distance (infinite
        if the die surface does not answer). */
    double unlimited_gap(const unsigned int k, const dealii::Point<dim> &x, const double t) const;

    /** Signed difference s1 - s0 on die @p die (wrapped on closed dies). */
    double
    die_coordinate_difference(const unsigned int die, const double s1, const double s0) const;

    /** Rebuild the friction row transforms from the current statuses. */
    void build_row_transforms();

    ContactParameters                                     parameters;
    std::vector<std::unique_ptr<RigidDie<dim>>>           dies;
    std::vector<Node>                                     nodes;
    RowTransforms<dim>                                    transforms;
    std::vector<std::unique_ptr<ContactTangentTerm<dim>>> tangents; ///< tangent_terms()
    MPI_Comm                                              comm = MPI_COMM_WORLD;
    double                                                time = 0.;
    double                                                gap_tolerance = 1e-10;
    double smallest_cell = 0.; ///< smallest cell diameter of the mesh (setup(): length_scale)
    /** 3D: slips over a step longer than this (1e-2 of the length scale) set the slip direction
        at every iterate (with its derivative in the tangent: SlipDirectionTangent); shorter
        ones keep it (update_slip_direction()). */
    double slip_length = 1e-8;
    /** 3D, nested active set: a turn of the slip direction (largest change of a component of
        the unit vector) beyond this at a converged state is one more pass (update_statuses()). */
    double direction_tolerance = 1e-8;
    /** Slip against the slip direction beyond this is a reversal (the node sticks). */
    double reversal_tolerance = 1e-10;
    double force_tolerance = 0.;
    double area_floor = 0.;      ///< tributary areas below this are zero (nodes on the axis)
    bool   hold_changed = false; ///< hold_changed_nodes()
  };
} // namespace ausroll::contact
