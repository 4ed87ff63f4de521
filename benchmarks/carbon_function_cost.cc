/**
 * @file carbon_function_cost.cc
 * Cost of Ms(C) (the default `Phases/Martensite start temperature`, Andrews' relation) per
 * material-point call: the muparser evaluation at every call (CarbonFunction::evaluate(), what
 * PhaseTransformationModel did before the memo) against the memoised CarbonFunction::value(),
 * for the carbon contents a workpiece's points cycle through: one value (uniform carbon), 192
 * values (a profile through the thickness of 64 cells with 3 points each), 100000 values (a
 * profile in two coordinates over 100000 points: more than the table's 4096 entries). Every
 * memoised value is compared with the evaluated one bit for bit (the program fails otherwise).
 *
 * Usage: carbon_function_cost [n_calls = 10000000]
 * CPU times of the process (clock_gettime(CLOCK_PROCESS_CPUTIME_ID)).
 */
#include <ausroll/material/carbon_function.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

namespace
{
  double cpu_nanoseconds()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e9 * t.tv_sec + t.tv_nsec;
  }
} // namespace

int main(int argc, char **argv)
{
  const long                              n = argc > 1 ? std::atol(argv[1]) : 10000000;
  const ausroll::material::CarbonFunction ms(
      "539 - 423*C - 30.4*0.55 - 17.7*3.25 - 12.1*1.2 - 7.5*0.12", "Ms");
  std::printf("| carbon values cycled | evaluate every call (ns) | memoised (ns) | ratio |\n");
  std::printf("|---|---|---|---|\n");
  for (const long distinct : {1L, 192L, 100000L})
  {
    std::vector<double> carbon(distinct);
    for (long k = 0; k < distinct; ++k)
      carbon[k] = 0.2 + 0.7 * k / double(distinct);
    double     sum_evaluated = 0., sum_memo = 0.;
    const auto t0 = cpu_nanoseconds();
    for (long i = 0; i < n; ++i)
      sum_evaluated += ms.evaluate(carbon[i % distinct]);
    const auto t1 = cpu_nanoseconds();
    for (long i = 0; i < n; ++i)
      sum_memo += ms.value(carbon[i % distinct]);
    const auto t2 = cpu_nanoseconds();
    for (long k = 0; k < distinct; ++k)
      if (ms.value(carbon[k]) != ms.evaluate(carbon[k]))
      {
        std::printf("memoised value differs at C = %.17g\n", carbon[k]);
        return 1;
      }
    if (sum_evaluated != sum_memo)
    {
      std::printf("sums differ\n");
      return 1;
    }
    std::printf("| %ld | %.1f | %.1f | %.1f |\n",
                distinct,
                (t1 - t0) / n,
                (t2 - t1) / n,
                (t1 - t0) / (t2 - t1));
  }
  return 0;
}
