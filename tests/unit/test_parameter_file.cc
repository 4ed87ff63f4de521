// Unit tests of the robust .prm reading (core/parameter_file.h) and of the parameter comparison
// on resume (io/checkpoint.h): overrides parsed like file lines, includes expanded with their
// cycles refused, numbers beyond 1e30 refused, discretisation changes refused on resume.
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/io/checkpoint.h>

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

using namespace ausroll;

namespace
{
  void declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Number of steps", "10", dealii::Patterns::Integer(1));
    prm.declare_entry("End time", "1", dealii::Patterns::Double());
    prm.leave_subsection();
  }

  std::string write(const std::filesystem::path &path, const std::string &text)
  {
    std::ofstream(path) << text;
    return path.string();
  }

  std::string message_of(const std::function<void()> &f)
  {
    try
    {
      f();
    }
    catch (const std::exception &e)
    {
      return e.what();
    }
    return "";
  }
} // namespace

TEST(ParameterFile, OverrideIsCheckedLikeAFileLine)
{
  const auto dir = std::filesystem::temp_directory_path() / "ausroll_test_parameter_file";
  std::filesystem::create_directories(dir);
  const std::string file
      = write(dir / "a.prm", "\xEF\xBB\xBFsubsection Loading\n  set End time = 2\nend\n");
  dealii::ParameterHandler prm;
  declare(prm);
  parse_parameter_text(
      prm, expand_parameter_file(file), {parse_override("Loading/Number of steps = 40")});
  const auto entries = flatten_parameters(prm);
  EXPECT_EQ(entries.at("Loading/Number of steps"), "40"); // the override
  EXPECT_EQ(entries.at("Loading/End time"), "2");         // the file (its BOM dropped)

  dealii::ParameterHandler bad;
  declare(bad);
  const std::string m = message_of(
      [&] {
        parse_parameter_text(bad, expand_parameter_file(file), {parse_override("Loading/Steps=4")});
      });
  EXPECT_NE(m.find("--set 'Loading/Steps=4'"), std::string::npos) << m;
  EXPECT_THROW(parse_override("Loading"), UsageError);
}

TEST(ParameterFile, IncludeCycleNamesTheChain)
{
  const auto dir = std::filesystem::temp_directory_path() / "ausroll_test_parameter_file";
  std::filesystem::create_directories(dir);
  write(dir / "b.inc", "include c.prm\n");
  const std::string c = write(dir / "c.prm", "include b.inc\n");
  const std::string m = message_of([&] { expand_parameter_file(c); });
  EXPECT_NE(m.find("c.prm -> "), std::string::npos) << m;
  EXPECT_NE(m.find("b.inc -> "), std::string::npos) << m;
}

TEST(ParameterFile, NumbersBeyond1e30AreRefused)
{
  EXPECT_NO_THROW(
      check_number_magnitudes({{"Material/Young's modulus", "2.1e5"},
                               {"Contact/Die 0/Motion/Prescribed/Translation", "0; -1e-3*t"},
                               {"Scene name", "nan test"}}));
  const std::string m = message_of(
      [] {
        check_number_magnitudes({{"Contact/Die 0/Circle/Radius", "1e308"}});
      });
  EXPECT_EQ(m.rfind("Contact/Die 0/Circle/Radius: '1e308' is out of range", 0), 0u) << m;
  EXPECT_THROW(check_number_magnitudes({{"Loading/End time", "inf"}}), InputError);
  EXPECT_THROW(check_number_magnitudes({{"Boundary conditions/Condition 0/Value", "t*1e31"}}),
               InputError);
}

TEST(Checkpoint, ResumeRefusesChangedDiscretisationAndWarnsOtherwise)
{
  io::CheckpointMetadata meta;
  meta.set_parameters({{"Geometry/Ring/Cells around", "48"},
                       {"Loading/End time", "1"},
                       {"Output/Overwrite", "false"}});
  // what was stored comes back (written as text and read again)
  const auto file = std::filesystem::temp_directory_path() / "ausroll_test_metadata.txt";
  meta.write(file.string());
  io::CheckpointMetadata read;
  read.read(file.string());
  EXPECT_EQ(read.parameters().at("Geometry/Ring/Cells around"), "48");

  const auto warnings = io::compare_resume_parameters(read,
                                                      {{"Geometry/Ring/Cells around", "48"},
                                                       {"Loading/End time", "2"},
                                                       {"Output/Overwrite", "true"}},
                                                      "out/checkpoint");
  ASSERT_EQ(warnings.size(), 1u); // End time; Overwrite does not change results
  EXPECT_NE(warnings[0].find("Loading/End time (checkpoint: '1', now: '2')"), std::string::npos);

  const std::string m = message_of(
      [&]
      {
        io::compare_resume_parameters(
            read, {{"Geometry/Ring/Cells around", "96"}, {"Loading/End time", "1"}}, "cp");
      });
  EXPECT_NE(m.find("Geometry/Ring/Cells around (checkpoint: '48', now: '96')"), std::string::npos)
      << m;
}
