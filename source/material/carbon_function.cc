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
    /** One remembered value: which function, which C and T (bit patterns; T's 0 for f(C)), f. */
    struct Slot
    {
      std::uint64_t serial = 0; // 0: empty (serial numbers start at 1)
      std::uint64_t bits = 0;
      std::uint64_t bits_t = 0;
      double        value = 0.;
    };

    /** The per-thread table (shared by all functions). */
    std::array<Slot, CarbonFunction::slots> &memo()
    {
      static thread_local std::array<Slot, CarbonFunction::slots> table;
      return table;
    }

    std::atomic<std::uint64_t> next_serial{1};

    std::uint64_t bits_of(const double C)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &C, sizeof bits);
      return bits;
    }
  } // namespace

  CarbonFunction::CarbonFunction(const std::string &expression,
                                 const std::string &entry,
                                 const bool         temperature)
      : serial(next_serial++)
  {
    require_expression_length(expression, entry);
    const std::string variables = temperature ? "C, T" : "C";
    const auto        cannot_parse = [&]()
    {
      return InputError(entry + ": cannot parse '" + abbreviate(expression) + "' (variable"
                        + (temperature ? "s: " : ": ") + variables + ")");
    };
    // muparser reports an unknown name at the first evaluation, not at initialize()
    const auto value_at = [&](const double C, const double T)
    {
      try
      {
        return temperature ? parser_ct->value(Point<2>(C, T)) : parser->value(Point<1>(C));
      }
      catch (const ExceptionBase &)
      {
        throw cannot_parse();
      }
    };
    try
    {
      if (temperature)
      {
        parser_ct = std::make_unique<FunctionParser<2>>(1);
        parser_ct->initialize("C,T", expression, std::map<std::string, double>{});
      }
      else
      {
        parser = std::make_unique<FunctionParser<1>>(1);
        parser->initialize("C", expression, std::map<std::string, double>{});
      }
    }
    catch (...)
    {
      throw cannot_parse();
    }
    for (unsigned int i = 0; i <= 21; ++i)
      for (unsigned int j = 0; j <= (temperature ? 20u : 0u); ++j)
        if (!std::isfinite(value_at(0.1 * i, 50. * j)))
          throw InputError(entry + ": '" + abbreviate(expression)
                           + "' is not finite at C = " + std::to_string(0.1 * i)
                           + (temperature ? ", T = " + std::to_string(50 * j) : std::string()));
  }

  double CarbonFunction::evaluate(const double C) const
  {
    return parser->value(Point<1>(C));
  }

  double CarbonFunction::evaluate(const double C, const double T) const
  {
    return parser_ct->value(Point<2>(C, T));
  }

  double CarbonFunction::value(const double C, const double T) const
  {
    const std::uint64_t bits = bits_of(C);
    const std::uint64_t bits_t = bits_of(T);
    // as value(C), with T's bits rotated into the key
    const std::uint64_t key
        = (bits ^ ((bits_t << 29) | (bits_t >> 35)) ^ (serial * 0xD6E8FEB86659FD93ull))
          * 0x9E3779B97F4A7C15ull;
    Slot &slot = memo()[key >> 52];
    if (slot.serial == serial && slot.bits == bits && slot.bits_t == bits_t)
      return slot.value;
    slot.serial = serial;
    slot.bits = bits;
    slot.bits_t = bits_t;
    slot.value = evaluate(C, T);
    return slot.value;
  }

  double CarbonFunction::value(const double C) const
  {
    auto               &table = memo();
    const std::uint64_t bits = bits_of(C);
    // Fibonacci hashing of the key (C's bits and the serial number) onto the 12-bit index
    const std::uint64_t key = (bits ^ (serial * 0xD6E8FEB86659FD93ull)) * 0x9E3779B97F4A7C15ull;
    Slot               &slot = table[key >> 52];
    static_assert(slots == 4096, "the index takes the 12 top bits of the key");
    if (slot.serial == serial && slot.bits == bits && slot.bits_t == 0)
      return slot.value;
    slot.serial = serial;
    slot.bits = bits;
    slot.bits_t = 0;
    slot.value = evaluate(C);
    return slot.value;
  }
} // namespace ausroll::material
