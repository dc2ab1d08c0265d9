// SPDX-License-Identifier: MIT
#include "solver/restart/restart_output.hpp"

#include <filesystem>

#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

RestartOutput::RestartOutput(const inputs::RestartOutputSpec& spec, std::string directory, std::string run_id)
    : spec_(spec), directory_(std::move(directory)), run_id_(std::move(run_id)), last_write_(std::chrono::steady_clock::now()) {}

bool RestartOutput::due(long step) {
  if (spec_.step_increment && step % *spec_.step_increment == 0) return true;
  if (!spec_.wall_time_increment) return false;
  // Checked every 16 steps: the wall clock of rank 0 decides for everyone (one broadcast).
  if (step % 16 != 0) return false;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count();
  int decision = elapsed >= *spec_.wall_time_increment ? 1 : 0;
  parallel::broadcast(&decision, 1, 0);
  return decision != 0;
}

std::string RestartOutput::write(const StateArchive& archive) {
  namespace fs = std::filesystem;
  const fs::path file = fs::path(directory_) / ("restart_" + std::to_string(next_slot_) + ".h5");
  write_restart_file(file.string(), archive, run_id_);
  if (parallel::is_root()) {
    // restart.h5 -> newest file of the ring, replaced atomically (link under a temporary name, rename).
    const fs::path latest = fs::path(directory_) / "restart.h5", tmp = fs::path(directory_) / "restart.h5.link";
    std::error_code ec;
    fs::remove(tmp, ec);
    fs::create_hard_link(file, tmp, ec);
    if (ec) fs::copy_file(file, tmp, fs::copy_options::overwrite_existing, ec);
    if (!ec) fs::rename(tmp, latest, ec);
  }
  parallel::barrier();
  next_slot_ = (next_slot_ + 1) % spec_.ring_size;
  last_write_ = std::chrono::steady_clock::now();
  return file.string();
}

}  // namespace tribex::solver
