/**
 * @file main.cc
 * Entry point of the GoogleTest unit-test executable `ausroll_unit_tests` (the executable links
 * GTest::gtest, not gtest_main). MPI is initialised because distributed triangulations and
 * Trilinos objects need it.
 */
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
