// SPDX-License-Identifier: MIT
#include "solver/errors.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>

#include "mesh/mesh_error.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

std::string no_space_reason(const std::string& what) {
  // `what` is a file, maybe with ":/dataset" or " (detail)" after it: its folder is measured.
  const std::size_t end = std::min(what.find(" ("), what.find(":/"));
  const std::filesystem::path file(end == std::string::npos ? what : std::string(what.begin(), what.begin() + long(end)));
  const std::string folder = file.has_parent_path() ? file.parent_path().string() : std::string(1, '.');
  struct statvfs fs {};
  std::string text = "no space left on device (";
  if (statvfs(folder.c_str(), &fs) == 0)
    text.append(std::to_string(static_cast<unsigned long long>(fs.f_bavail) * fs.f_frsize)).append(" bytes free in ");
  return text.append(folder).append(")");
}

OutputError output_failure(const std::string& path, int error_number) {
  if (error_number == ENOMEM)  // a library's allocation failed while writing (HDF5's buffers)
    return OutputError("out of memory while writing " + path + "; run on more ranks or a machine with more memory; the " +
                       "files up to the last complete output step are kept");
  const bool full = error_number == ENOSPC || error_number == EDQUOT;
  const std::string reason = full ? no_space_reason(path) : error_number ? std::strerror(error_number) : "write failed";
  return OutputError(reason + " while writing " + path +
                     "; free space on the device or choose another output folder (-o); the files up to the last "
                     "complete output step are kept");
}

SetupError orphan_node_error(int node) {
  return SetupError("mesh node " + std::to_string(node + 1) + " belongs to no element (zero mass); remove it from the mesh");
}

int exit_code_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const SetupError&) {
    return 2;
  } catch (const mesh::MeshError&) {
    return 2;
  } catch (const NumericalFailure&) {
    return 3;
  } catch (const std::bad_alloc&) {
    return 2;  // out of memory in set-up (DeckRun names the stage and the size)
  } catch (const StoppedByOtherRank& s) {
    return s.exit_code;
  } catch (...) {
    return 1;
  }
}

void agree_on_errors(const std::exception_ptr& error) {
  if (parallel::size() == 1) {
    if (error) std::rethrow_exception(error);
    return;
  }
  const double first = parallel::min(error ? double(parallel::rank()) : 1e9);
  if (first >= 1e9) return;
  int code = error ? exit_code_of(error) : 0;
  parallel::broadcast(&code, 1, static_cast<int>(first));
  if (parallel::rank() == static_cast<int>(first)) std::rethrow_exception(error);
  throw StoppedByOtherRank(code);
}

}  // namespace tribex::solver
