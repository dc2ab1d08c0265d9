// SPDX-License-Identifier: MIT
// The full state of a run as named flat arrays: what a restart file holds (each rank's, restart_file.cpp).
// Every part of the solver that carries state between steps (integrator, element blocks, contact,
// output schedules) writes its arrays here under its own prefix and reads them back; see
// solver/README.md "Parallel runs and restart: rules for model authors".
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "solver/errors.hpp"

namespace tribex::solver {

struct StateArchive {
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<long long>> integers;

  void put(const std::string& name, const std::vector<double>& v) { reals[name] = v; }
  void put(const std::string& name, double x) { reals[name] = {x}; }
  void put_integers(const std::string& name, const std::vector<long long>& v) { integers[name] = v; }
  void put_integer(const std::string& name, long long x) { integers[name] = {x}; }
  template <class Int>
  void put_ints(const std::string& name, const std::vector<Int>& v) {
    integers[name] = std::vector<long long>(v.begin(), v.end());
  }

  const std::vector<double>& array(const std::string& name) const {
    auto it = reals.find(name);
    if (it == reals.end() && integers.count(name))  // issue 54, item 17: an edited file's integer `u`
      throw SetupError("restart dataset '" + name + "' is integer-typed; tribex writes it as float64 (an edited restart file?)");
    if (it == reals.end()) throw SetupError("restart file lacks '" + name + "' (written by another tribex version?)");
    return it->second;
  }
  /// Copies array `name` into `out`, which must already have the size it had when written.
  void get(const std::string& name, std::vector<double>& out) const {
    const auto& a = array(name);
    if (a.size() != out.size())
      throw SetupError("restart file: '" + name + "' has " + std::to_string(a.size()) + " values, the model needs " +
                       std::to_string(out.size()) + " (a different mesh or deck?)");
    out = a;
  }
  bool has(const std::string& name) const { return reals.count(name) > 0 || integers.count(name) > 0; }
  double scalar(const std::string& name) const {
    const auto& a = array(name);
    if (a.size() != 1) throw SetupError("restart file: '" + name + "' is not a scalar");
    return a[0];
  }
  const std::vector<long long>& integer_array(const std::string& name) const {
    auto it = integers.find(name);
    if (it == integers.end() && reals.count(name))
      throw SetupError("restart dataset '" + name + "' is float-typed; tribex writes it as int64 (an edited restart file?)");
    if (it == integers.end()) throw SetupError("restart file lacks '" + name + "' (written by another tribex version?)");
    return it->second;
  }
  long long integer(const std::string& name) const {
    const auto& a = integer_array(name);
    if (a.size() != 1) throw SetupError("restart file: '" + name + "' is not a scalar");
    return a[0];
  }
  template <class Int>
  void get_ints(const std::string& name, std::vector<Int>& out) const {
    const auto& a = integer_array(name);
    out.assign(a.begin(), a.end());
  }
};

/// Writes `archive` of this rank into `path` (all ranks at once with parallel HDF5, each its slice of
/// every entry: restart_file.cpp), through `path`.part and a rename so that a crash never
/// leaves a half-written restart file under its final name. Collective over the run's ranks.
/// run_id (may be ""): the run's identity, a string attribute `run_id` on the file (README.md "The
/// output folder"): a resumed run keeps it, and continues only that run's output folder.
void write_restart_file(const std::string& path, const StateArchive& archive, const std::string& run_id = "");

/// A restart file opened for reading its groups one at a time (restart_remap.cpp reads those a rank
/// needs when the file was written by another rank count). The constructor checks the file is a
/// tribex restart file of format version 1 or 2 (SetupError, exit 2, otherwise).
class RestartFile {
 public:
  explicit RestartFile(const std::string& path);
  ~RestartFile();
  RestartFile(const RestartFile&) = delete;
  RestartFile& operator=(const RestartFile&) = delete;
  /// The rank count that wrote the file (its parts 0 .. ranks - 1; version 1: groups rank_<g>).
  int ranks() const { return ranks_; }
  const std::string& path() const { return path_; }
  /// Rank g's arrays: every one, or those `wanted` accepts (an empty function: every one).
  StateArchive read_group(int g, const std::function<bool(const std::string&)>& wanted = {}) const;

 private:
  std::string path_;
  std::int64_t file_ = -1;  // hid_t
  int ranks_ = 0;
  std::uintmax_t file_bytes_ = 0;
};

/// Reads this rank's group. Throws SetupError (exit 2) when the file is missing or unreadable,
/// or was written by a different number of ranks.
StateArchive read_restart_file(const std::string& path);

}  // namespace tribex::solver
