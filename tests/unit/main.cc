/**
 * @file main.cc
 * Entry point of the GoogleTest unit-test executable `ausroll_unit_tests` (the executable links
 * GTest::gtest, not gtest_main) and initialises MPI.
 */
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  // MPI (one thread) for the tests that use Trilinos vectors (assembler).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
