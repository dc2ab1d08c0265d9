// SPDX-License-Identifier: MIT
// main() of the GoogleTest executables run under mpiexec (tests/parallel_unit/CMakeLists.txt): MPI
// around the tests, rank 0 alone prints, and every rank exits failed if any rank failed.
#include <gtest/gtest.h>
#include <mpi.h>

#include "solver/parallel/communicator.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (tribex::solver::parallel::rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS();
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return failed;
}
