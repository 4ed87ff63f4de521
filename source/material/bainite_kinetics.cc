#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/bainite_kinetics.h>

#include <cmath>

namespace ausroll::material
{
  namespace
  {
    /** ln(ln(1 - 0.99) / ln(1 - 0.01)): n ln(t_f / t_s) of the JMAK law through both points. */
    const double log_ratio = std::log(std::log(0.01) / std::log(0.99));
  } // namespace

  BainiteKinetics::BainiteKinetics(const std::string &start,
                                   const std::string &finish,
                                   const std::string &start_entry,
                                   const std::string &finish_entry,
                                   const std::string &input_directory)
  {
    const bool has_start = !split_and_trim(start, ',').empty();
    const bool has_finish = !split_and_trim(finish, ',').empty();
    if (!has_start && !has_finish)
      return;
    require(has_start, start_entry, "is empty but " + finish_entry + " is given: give both");
    require(has_finish, finish_entry, "is empty but " + start_entry + " is given: give both");
    start_time = PropertyTable::parse(start, start_entry, input_directory, true);
    finish_time = PropertyTable::parse(finish, finish_entry, input_directory, true);
    require(!start_time.is_constant(),
            start_entry,
            "needs rows 'T: t_s' over the bainite range (at least two temperatures)");
    require(start_time.row_temperatures() == finish_time.row_temperatures(),
            finish_entry,
            "must give the times at the same temperatures as " + start_entry);
    const std::vector<double> &T = start_time.row_temperatures();
    for (unsigned int i = 0; i < T.size(); ++i)
      require(finish_time.value(T[i]) > start_time.value(T[i]),
              finish_entry,
              "the finish time must be later than the start time at every temperature (row "
                  + std::to_string(i + 1) + ", T = " + std::to_string(T[i]) + ")");
    lowest = T.front();
    highest = T.back();
    enabled = true;
  }

  double BainiteKinetics::exponent(const double T) const
  {
    return log_ratio / std::log(finish_time.value(T) / start_time.value(T));
  }

  double BainiteKinetics::rate(const double T) const
  {
    return rate(T, exponent(T));
  }

  double BainiteKinetics::rate(const double T, const double n) const
  {
    return -std::log(0.99) / std::pow(start_time.value(T), n);
  }

  double BainiteKinetics::advance(const double xi_old, const double T, const double dt) const
  {
    if (!in_range(T) || !(dt > 0.) || xi_old >= 1.)
      return xi_old;
    const double n = exponent(T);
    const double k = rate(T, n);
    const double t_star = xi_old > 0. ? std::pow(-std::log1p(-xi_old) / k, 1. / n) : 0.;
    return std::max(xi_old, -std::expm1(-k * std::pow(t_star + dt, n)));
  }
} // namespace ausroll::material
