// SPDX-License-Identifier: MIT
// Scoped use of the gmsh C++ API, which is one process-wide state machine (gmsh 4.8).
//
//   { GmshSession gmsh;            // gmsh::initialize on the first live session, finalize on the last
//     GmshScratchModel model("x"); // a fresh model, removed again at scope exit
//     ... gmsh::model::... calls ... }
//
// Sessions nest (read_gmsh inside a test that builds a mesh with the gmsh API) and are serialised
// across threads by one recursive mutex held for the session's lifetime.
#pragma once

#include <string>

namespace tribex::mesh {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// Makes a new empty gmsh model current; on destruction removes it and makes the previously current
/// model current again. Needs a live GmshSession.
class GmshScratchModel {
 public:
  explicit GmshScratchModel(const std::string& purpose);
  ~GmshScratchModel();
  GmshScratchModel(const GmshScratchModel&) = delete;
  GmshScratchModel& operator=(const GmshScratchModel&) = delete;

 private:
  std::string previous_;
};

}  // namespace tribex::mesh
