/**
 * @file test_parameter_round_trip.cc
 * Parameter round trip: the complete scene parameter tree printed as a .prm file, parsed back and
 * printed again gives the identical text (defaults, and shipped scenes with many non-default
 * entries); the printed file also parses into the SceneParameters struct with the same values.
 */
#include <ausroll/contact/friction/coulomb.h>
#include <ausroll/contact/motion/prescribed.h>
#include <ausroll/io/parameter_documentation.h>
#include <ausroll/scene/scene_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

using ausroll::scene::SceneParameters;
using dealii::ParameterHandler;

namespace
{
  std::string print(const ParameterHandler &prm)
  {
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::OutputStyle::PRM);
    return out.str();
  }

  /** print -> parse -> print of the tree after reading @p input; returns both prints. */
  std::pair<std::string, std::string> round_trip(const std::string &input)
  {
    ParameterHandler first;
    SceneParameters::declare_parameters(first);
    first.parse_input_from_string(input, "input", /*skip_undefined=*/false);
    const std::string printed = print(first);

    ParameterHandler second;
    SceneParameters::declare_parameters(second);
    second.parse_input_from_string(printed, "printed", /*skip_undefined=*/false);
    return {printed, print(second)};
  }

  std::string read_file(const std::string &name)
  {
    std::ifstream      in(name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace

TEST(ParameterRoundTrip, DefaultsPrintParsePrintIdentical)
{
  const auto [printed, reprinted] = round_trip("");
  EXPECT_GT(printed.size(), 10000u);
  EXPECT_EQ(printed, reprinted);
  // the Markdown reference of the same tree is stable too
  ParameterHandler prm;
  SceneParameters::declare_parameters(prm);
  std::ostringstream a, b;
  ausroll::io::print_parameters(a, "markdown", prm);
  ausroll::io::print_parameters(b, "markdown", prm);
  EXPECT_EQ(a.str(), b.str());
  EXPECT_NE(a.str().find("`Friction factor`"), std::string::npos);
}

TEST(ParameterRoundTrip, ShippedScenesPrintParsePrintIdentical)
{
  // scenes without relative includes or files (the printed file is parsed from a string)
  for (const std::string name : {"/tests/checks/scenes/block_slide.prm",
                                 "/tests/checks/scenes/thick_sphere_follower.prm",
                                 "/tests/upsetting_short.prm",
                                 "/prm/thick_cylinder.prm"})
  {
    const std::string text = read_file(AUSROLL_SOURCE_DIR + name);
    ASSERT_FALSE(text.empty()) << name;
    const auto [printed, reprinted] = round_trip(text);
    EXPECT_EQ(printed, reprinted) << name;

    // the printed file holds the scene's values: both parse to the same struct values
    ParameterHandler original, copy;
    SceneParameters::declare_parameters(original);
    SceneParameters::declare_parameters(copy);
    original.parse_input_from_string(text, name, false);
    copy.parse_input_from_string(printed, "printed", false);
    SceneParameters a, b;
    a.parse_parameters(original, "");
    b.parse_parameters(copy, "");
    EXPECT_EQ(a.name, b.name) << name;
    EXPECT_EQ(a.material.yield_stress.min_value(), b.material.yield_stress.min_value()) << name;
    EXPECT_EQ(a.material.yield_stress.max_value(), b.material.yield_stress.max_value()) << name;
    EXPECT_EQ(a.loading.end_time, b.loading.end_time) << name;
    EXPECT_EQ(a.contact.dies.size(), b.contact.dies.size()) << name;
    for (unsigned int k = 0; k < a.contact.dies.size(); ++k)
    {
      EXPECT_EQ(a.contact.dies[k].friction_law, b.contact.dies[k].friction_law);
      const auto *coulomb_a = dynamic_cast<const ausroll::contact::CoulombParameters *>(
          a.contact.dies[k].friction.get());
      const auto *coulomb_b = dynamic_cast<const ausroll::contact::CoulombParameters *>(
          b.contact.dies[k].friction.get());
      ASSERT_EQ(coulomb_a == nullptr, coulomb_b == nullptr) << name;
      if (coulomb_a != nullptr)
        EXPECT_EQ(coulomb_a->mu, coulomb_b->mu) << name;
      EXPECT_EQ(a.contact.dies[k].motion_type, b.contact.dies[k].motion_type);
      const auto *prescribed_a = dynamic_cast<const ausroll::contact::PrescribedMotionParameters *>(
          a.contact.dies[k].motion.get());
      const auto *prescribed_b = dynamic_cast<const ausroll::contact::PrescribedMotionParameters *>(
          b.contact.dies[k].motion.get());
      ASSERT_EQ(prescribed_a == nullptr, prescribed_b == nullptr) << name;
      if (prescribed_a != nullptr)
        EXPECT_EQ(prescribed_a->translation, prescribed_b->translation) << name;
    }
    EXPECT_EQ(a.boundary_conditions.conditions.size(), b.boundary_conditions.conditions.size());
  }
}
