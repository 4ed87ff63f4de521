/**
 * @file main.cc
 * Entry point of the GoogleTest unit-test executable `ausroll_unit_tests` (the executable links
 * GTest::gtest, not gtest_main).
 */
#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
