#include <ausroll/io/postprocess/die_forces.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <cmath>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  void DieForces<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    const contact::ContactOperator<dim> &contact = input.contact;
    for (unsigned int k = 0; k < contact.n_dies(); ++k)
    {
      const contact::RigidDie<dim> &die = contact.die(k);
      const auto                    c = contact.die_contact(k);
      const contact::DiePose<dim>   pose = die.pose(input.time);
      const std::string             p = "die_" + die.name + "_";
      for (unsigned int d = 0; d < dim; ++d)
        row.emplace_back(p + "force_" + std::string(1, "xyz"[d]), c.force[d]);
      row.emplace_back(p + "x", pose.reference_position()[0]);
      row.emplace_back(p + "y", pose.reference_position()[1]);
      if constexpr (dim == 3)
        row.emplace_back(p + "z", pose.reference_position()[2]);
      row.emplace_back(p + "angle", pose.angle() * 180. / M_PI);
      row.emplace_back(p + "stick_nodes", c.n_stick);
      row.emplace_back(p + "slip_nodes", c.n_slip);
      row.emplace_back(p + "contact_length", c.contact_length);
      row.emplace_back(p + "contact_width", c.contact_width);
      if (const contact::RollingMotion<dim> *rolling = die.rolling_motion())
      {
        if constexpr (dim == 2)
          rolling_columns(*rolling, input.time, Tensor<1, 2>({c.force[0], c.force[1]}), p, row);
        else
          rolling_columns(*rolling, input.time, c.force, c.moment, p, row);
      }
    }
  }

  void rolling_columns(const contact::RollingMotion<3> &rolling,
                       const double                     time,
                       const Tensor<1, 3>              &force,
                       const Tensor<1, 3>              &moment,
                       const std::string               &prefix,
                       HistoryRow                      &row)
  {
    // the planar columns in the plane orthogonal to the axis a, then the axial force and the
    // torque about the die axis
    const auto        &d = rolling.data();
    const Tensor<1, 3> a = d.axis / d.axis.norm();
    Tensor<1, 3>       e_r = rolling.die_center(time) - d.workpiece_center;
    e_r -= (e_r * a) * a;
    e_r /= e_r.norm();
    const Tensor<1, 3> e_t = cross_product_3d(a, e_r);
    const double       a0 = d.initial_center_distance.value_or(d.workpiece_radius + d.die_radius);
    row.emplace_back(prefix + "revolution",
                     d.direction * (rolling.line_angle(time) - d.initial_line_angle) * 180. / M_PI);
    row.emplace_back(prefix + "feed", a0 - rolling.center_distance(time));
    row.emplace_back(prefix + "force_radial", force * e_r);
    row.emplace_back(prefix + "force_tangential", force * e_t);
    row.emplace_back(prefix + "force_axial", force * a);
    row.emplace_back(prefix + "force_magnitude", force.norm());
    row.emplace_back(prefix + "torque", moment * a);
  }

  void rolling_columns(const contact::RollingMotion<2> &rolling,
                       const double                     time,
                       const Tensor<1, 2>              &force,
                       const std::string               &prefix,
                       HistoryRow                      &row)
  {
    const auto        &d = rolling.data();
    const double       psi = rolling.line_angle(time);
    const Tensor<1, 2> e_r({std::cos(psi), std::sin(psi)});
    const Tensor<1, 2> e_t({-e_r[1], e_r[0]});
    const double       a0 = d.initial_center_distance.value_or(d.workpiece_radius + d.die_radius);
    row.emplace_back(prefix + "revolution",
                     d.direction * (psi - d.initial_line_angle) * 180. / M_PI);
    row.emplace_back(prefix + "feed", a0 - rolling.center_distance(time));
    row.emplace_back(prefix + "force_radial", force * e_r);
    row.emplace_back(prefix + "force_tangential", force * e_t);
    row.emplace_back(prefix + "force_magnitude", force.norm());
  }

  template <int dim>
  Unit DieForces<dim>::unit(const std::string &column) const
  {
    auto ends_with = [&column](const std::string &suffix)
    {
      return column.size() >= suffix.size()
             && column.compare(column.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    // the column name after its prefix die_<Name>_ (a die name may contain '_')
    for (const char *force : {"_force_x",
                              "_force_y",
                              "_force_z",
                              "_force_radial",
                              "_force_tangential",
                              "_force_axial",
                              "_force_magnitude"})
      if (ends_with(force))
        return {"force", "N"};
    if (ends_with("_torque"))
      return {"moment", "N mm"};
    if (ends_with("_angle") || ends_with("_revolution"))
      return {"angle", "deg"};
    if (ends_with("_stick_nodes") || ends_with("_slip_nodes"))
      return {"count", "1"};
    return {"length", "mm"}; // x, y, z, contact_length, contact_width, feed
  }

  template class DieForces<2>;
  template class DieForces<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_die_forces(const PostprocessorContext &)
    {
      return std::make_unique<DieForces<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_die_forces,
                               "die forces",
                               50,
                               "force, torque and motion of each die")
