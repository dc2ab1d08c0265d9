// SPDX-License-Identifier: MIT
#include "solver/output/output_folder.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <set>
#include <system_error>
#include <utility>

#include "solver/errors.hpp"
#include "solver/output/exodus_rank_file.hpp"

namespace tribex::solver {
namespace fs = std::filesystem;
namespace {

using FileKey = std::pair<unsigned long long, unsigned long long>;  // device, inode

std::optional<FileKey> lstat_key(const fs::path& p) {
  struct stat st{};
  if (lstat(p.c_str(), &st) != 0) return std::nullopt;
  return FileKey{static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino)};
}

// The files the deck reads, by device and inode (a path through another name or a hard link is the same file).
std::set<FileKey> input_keys(const std::vector<std::string>& inputs) {
  std::set<FileKey> keys;
  for (const auto& p : inputs) {
    struct stat st{};
    if (!p.empty() && stat(p.c_str(), &st) == 0)
      keys.insert({static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino)});
  }
  return keys;
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size() && k < 6; ++k) out += (k ? ", " : "") + names[k];
  if (names.size() > 6) out += " and " + std::to_string(names.size() - 6) + " more";
  return out;
}

// Missing folders are made, and removed again (when still empty) unless the claim succeeds: an
// exit 2 leaves no trace of a folder that was not there.
class MadeFolders {
 public:
  explicit MadeFolders(const fs::path& folder) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(folder, ec))) {
      if (!fs::is_directory(folder, ec))
        throw SetupError("output folder " + folder.string() + " exists and is not a folder; choose another (-o)");
      return;
    }
    for (fs::path p = folder; !p.empty() && !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path()) {
      made_.push_back(p);
      if (p == p.parent_path()) break;
    }
    fs::create_directories(folder, ec);
    if (ec) {
      release();
      throw SetupError("cannot create output folder " + folder.string() + ": " + ec.message() +
                       "; choose another output folder (-o) or fix its permissions");
    }
  }
  ~MadeFolders() { release(); }
  void keep() { made_.clear(); }

 private:
  void release() {
    std::error_code ec;
    for (const auto& p : made_) fs::remove(p, ec);  // deepest first; only an empty folder goes
    made_.clear();
  }
  std::vector<fs::path> made_;
};

// What the claim finds in the folder for the names this run writes and the earlier run's files.
struct Survey {
  std::vector<std::string> foreign;      // a planned name present that is not the earlier run's file
  std::vector<std::string> inputs;       // a planned name present that the deck reads
  std::vector<std::string> remove;       // the earlier run's files, still as written (fresh run)
  std::vector<std::string> kept_inputs;  // the earlier run's files the deck reads (kept)
};

Survey survey(const FolderRequest& r, const std::optional<OutputManifest>& old) {
  const std::set<FileKey> inputs = input_keys(r.inputs);
  const std::set<std::string> planned(r.names.begin(), r.names.end());
  Survey s;
  const auto ours = [&](const std::string& name) {
    const ManifestEntry* e = old ? old->find(name) : nullptr;
    return e && written_by_run(r.folder, *e, old->run_id);
  };
  for (const auto& name : r.names) {
    const auto key = lstat_key(r.folder / name);
    if (!key) continue;
    if (inputs.count(*key)) s.inputs.push_back(name);
    else if (!ours(name)) s.foreign.push_back(name);
  }
  if (!old || r.resume) return s;
  for (const auto& e : old->files) {
    const auto key = lstat_key(r.folder / e.name);
    if (!key) continue;
    if (inputs.count(*key)) s.kept_inputs.push_back(e.name);
    else if (written_by_run(r.folder, e, old->run_id)) s.remove.push_back(e.name);
  }
  return s;
}

// A resumed run continues only its own run's folder (or starts new files in a folder without outputs).
void check_resume(const FolderRequest& r, const std::optional<OutputManifest>& old) {
  if (!old) return;
  const std::string theirs = "run " + old->run_id + " (deck " + old->deck + ", started " + old->started + " on " +
                             old->host + ")";
  if (r.restart_run_id != old->run_id)
    throw SetupError(
        "cannot resume into output folder " + r.folder.string() + ": it holds the outputs of " + theirs + ", but " +
        r.restart_path + " was written by " +
        (r.restart_run_id.empty() ? std::string("a tribex that did not record run identities")
                                  : "run " + r.restart_run_id) +
        "; resume into the output folder of the run that wrote the restart file, or into a new one (-o)");
  if (!old->mesh_sha256.empty() && old->mesh_sha256 != r.identity.mesh_sha256)
    throw SetupError("cannot resume into output folder " + r.folder.string() +
                     ": the mesh differs from the one its results files hold (mesh sha256 " +
                     old->mesh_sha256.substr(0, 12) + "... then, " + r.identity.mesh_sha256.substr(0, 12) +
                     "... now) and a results file holds one mesh; resume into a new output folder (-o) to start new "
                     "results files there");
}

void refuse(const FolderRequest& r, const Survey& s) {
  if (!s.inputs.empty())
    throw SetupError("the deck reads " + listed(s.inputs) + " in output folder " + r.folder.string() +
                     ", which this run would write; choose another output folder (-o), or move the input out of it");
  if (!s.foreign.empty())
    throw SetupError("output folder " + r.folder.string() + " holds " + listed(s.foreign) +
                     ", which this run would write but no earlier tribex run there wrote (" + manifest_file_name +
                     " does not list them as its own, unchanged); tribex never replaces files it did not write: "
                     "move them away, or choose another output folder (-o)");
}

}  // namespace

std::vector<std::string> planned_output_names(bool xdmf, bool exodus, int ring_size, int ranks) {
  std::vector<std::string> names = {"log.txt", "history.csv", "history_columns.csv", "summary.json", "summary.json.tmp"};
  if (xdmf) names.insert(names.end(), {"results.h5", "results.xdmf", "results.xdmf.tmp"});
  if (exodus && ranks == 1) names.insert(names.end(), {"results.exo", ".results.exo.partial"});
  for (int r = 0; exodus && ranks > 1 && r < ranks; ++r) {  // one file per rank and its restart rewrite's copy
    const std::string name = output::rank_file_name(ranks, r);
    names.insert(names.end(), {name, "." + name + ".partial"});
  }
  for (int k = 0; k < ring_size; ++k) {
    names.push_back("restart_" + std::to_string(k) + ".h5");
    names.push_back("restart_" + std::to_string(k) + ".h5.part");
  }
  if (ring_size > 0) names.insert(names.end(), {"restart.h5", "restart.h5.link"});
  return names;
}

void check_path_lengths(const fs::path& folder, const std::vector<std::string>& names) {
  for (const auto& part : folder)
    if (part.string().size() > NAME_MAX)
      throw SetupError("output folder path: its part '" + part.string().substr(0, 40) + "...' is " +
                       std::to_string(part.string().size()) + " characters, over the system's limit of " +
                       std::to_string(NAME_MAX) + " (NAME_MAX); choose a shorter output folder (-o)");
  std::string longest;
  for (const auto& name : names)
    if ((folder / name).string().size() > longest.size()) longest = (folder / name).string();
  if (longest.size() >= PATH_MAX)
    throw SetupError("output folder path is " + std::to_string(folder.string().size()) +
                     " characters: the files tribex writes in it (longest " + std::to_string(longest.size()) +
                     " characters) exceed the system's limit of " + std::to_string(PATH_MAX - 1) +
                     " (PATH_MAX); choose a shorter output folder (-o)");
}

void check_free_descriptors(int needed) {
  std::vector<int> fds;
  int err = 0;
  for (int k = 0; k < needed; ++k) {
    const int fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
      err = errno;
      break;
    }
    fds.push_back(fd);
  }
  const int opened = static_cast<int>(fds.size());
  for (int fd : fds) close(fd);
  if (opened == needed) return;
  struct rlimit limit{};
  getrlimit(RLIMIT_NOFILE, &limit);
  throw SetupError("too many open files (ulimit -n): the run needs " + std::to_string(needed) +
                   " more file descriptors for its outputs, and " + std::to_string(opened) +
                   " more can be opened (limit " + std::to_string(static_cast<long long>(limit.rlim_cur)) + ", " +
                   std::strerror(err) + "); raise the limit (e.g. ulimit -n 1024) and run again");
}

FolderClaim claim_output_folder(const FolderRequest& r) {
  std::vector<std::string> own = r.names;
  own.insert(own.end(), {OutputLock::file_name, manifest_file_name, std::string(manifest_file_name) + ".tmp"});
  check_path_lengths(r.folder, own);
  check_free_descriptors(r.descriptors_needed);
  MadeFolders made(r.folder);
  FolderClaim claim;
  claim.lock = std::make_unique<OutputLock>(
      r.folder, lock_holder_text(r.identity.host, r.identity.started, r.identity.run_id));
  const std::optional<OutputManifest> old = read_manifest(r.folder);
  if (r.resume) check_resume(r, old);
  const Survey s = survey(r, old);
  refuse(r, s);
  // Every check passed: from here the folder changes.
  for (const auto& name : s.remove) {
    std::error_code ec;
    fs::remove(r.folder / name, ec);
    if (ec)
      throw SetupError("cannot remove the earlier run's " + (r.folder / name).string() + " (" + ec.message() +
                       "); remove it or choose another output folder (-o)");
  }
  claim.removed = s.remove;
  claim.kept_inputs = s.kept_inputs;
  claim.manifest = r.identity;
  if (r.resume && old) {
    claim.manifest.files = old->files;
    claim.manifest.segments = old->segments;
  }
  for (const auto& name : r.names) claim.manifest.add(name);
  write_manifest(r.folder, claim.manifest);
  made.keep();
  return claim;
}

void record_written_files(const fs::path& folder, OutputManifest& manifest) {
  for (auto& e : manifest.files) {
    struct stat st{};
    if (lstat((folder / e.name).c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    e.device = static_cast<unsigned long long>(st.st_dev);
    e.inode = static_cast<unsigned long long>(st.st_ino);
  }
  write_manifest(folder, manifest);
}

}  // namespace tribex::solver
