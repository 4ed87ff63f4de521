/**
 * @file material_point.h
 * One material point (quadrature point) of the workpiece.
 */
#pragma once

#include <ausroll/material/material_state.h>

namespace ausroll::material
{
  /**
   * A quadrature point's data, stored in a dealii::CellDataStorage: the state of the last converged
   * load step (@ref committed) and the state computed for the current Newton iterate (@ref trial).
   * The committed state changes only in commit(), after a converged step.
   */
  class MaterialPoint
  {
  public:
    MaterialState committed; ///< state at the end of the last converged step
    MaterialState trial;     ///< state at the current iterate of the current step

    /** Accept the trial state (called once per converged step). */
    void commit() { committed = trial; }

    /** Discard the trial state (called when a step is cut back). */
    void reset_trial() { trial = committed; }
  };
} // namespace ausroll::material
