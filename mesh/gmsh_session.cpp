// SPDX-License-Identifier: MIT
#include "mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <mutex>

namespace tribex::mesh {

namespace {
std::recursive_mutex& gmsh_mutex() {
  static std::recursive_mutex m;
  return m;
}
int live_sessions = 0;  // guarded by gmsh_mutex()
int scratch_counter = 0;
}  // namespace

GmshSession::GmshSession() {
  gmsh_mutex().lock();
  if (live_sessions++ == 0) {
    // readConfigFiles = false: a user's ~/.gmshrc must not change how we read or write meshes.
    char arg0[] = "tribex";
    char* argv[] = {arg0, nullptr};
    try {
      gmsh::initialize(1, argv, false);
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings only, into the logger
    } catch (...) {  // no destructor will run: undo the count and the lock
      --live_sessions;
      gmsh_mutex().unlock();
      throw;
    }
  }
}

GmshSession::~GmshSession() {
  if (--live_sessions == 0) {
    try {
      gmsh::finalize();
    } catch (...) {  // a destructor must not throw; gmsh 4.8 throws std::string
    }
  }
  gmsh_mutex().unlock();
}

GmshScratchModel::GmshScratchModel(const std::string& purpose) {
  gmsh::model::getCurrent(previous_);
  gmsh::model::add("tribex_" + purpose + "_" + std::to_string(++scratch_counter));
}

GmshScratchModel::~GmshScratchModel() {
  try {
    gmsh::model::remove();
    gmsh::model::setCurrent(previous_);
  } catch (...) {
  }
}

}  // namespace tribex::mesh
