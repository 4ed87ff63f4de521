/**
 * @file carbon_function.cc
 * Memoised functions of the carbon content (see carbon_function.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/carbon_function.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstring>

namespace ausroll::material
{
  using namespace dealii;

  namespace
  {
    /** One remembered value: which function, which C (bit pattern), f(C). */
    struct Slot
    {
      std::uint64_t serial = 0; // 0: empty (serial numbers start at 1)
      std::uint64_t bits = 0;
      double        value = 0.;
    };

    std::atomic<std::uint64_t> next_serial{1};

    std::uint64_t bits_of(const double C)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &C, sizeof bits);
      return bits;
    }
  } // namespace

  CarbonFunction::CarbonFunction(const std::string &expression, const std::string &entry)
      : parser(std::make_unique<FunctionParser<1>>(1))
      , serial(next_serial++)
  {
    require_expression_length(expression, entry);
    try
    {
      parser->initialize("C", expression, std::map<std::string, double>{});
    }
    catch (...)
    {
      throw InputError(entry + ": cannot parse '" + abbreviate(expression) + "' (variable: C)");
    }
    for (unsigned int i = 0; i <= 21; ++i)
      if (!std::isfinite(parser->value(Point<1>(0.1 * i))))
        throw InputError(entry + ": '" + abbreviate(expression)
                         + "' is not finite at C = " + std::to_string(0.1 * i));
  }

  double CarbonFunction::evaluate(const double C) const
  {
    return parser->value(Point<1>(C));
  }

  double CarbonFunction::value(const double C) const
  {
    static thread_local std::array<Slot, slots> table;
    const std::uint64_t                         bits = bits_of(C);
    // Fibonacci hashing of the key (C's bits and the serial number) onto the 12-bit index
    const std::uint64_t key = (bits ^ (serial * 0xD6E8FEB86659FD93ull)) * 0x9E3779B97F4A7C15ull;
    Slot               &slot = table[key >> 52];
    static_assert(slots == 4096, "the index takes the 12 top bits of the key");
    if (slot.serial == serial && slot.bits == bits)
      return slot.value;
    slot.serial = serial;
    slot.bits = bits;
    slot.value = evaluate(C);
    return slot.value;
  }
} // namespace ausroll::material
