// SPDX-License-Identifier: MIT
// The output folder as a resource the run owns (README.md "The output folder"): every check before
// any file is touched, the lock, the manifest, and removing exactly the earlier run's files.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "solver/output/output_lock.hpp"
#include "solver/output/output_manifest.hpp"

namespace tribex::solver {

/// What a run asks of its output folder.
struct FolderRequest {
  std::filesystem::path folder;
  std::vector<std::string> names;    // every file this run may write there (planned_output_names)
  std::vector<std::string> inputs;   // every file the deck reads (deck, includes, mesh, data files)
  OutputManifest identity;           // this run: run_id, deck, hashes, start, host (files empty)
  bool resume = false;               // resumed from a restart file
  std::string restart_path;          // resume: the restart file and the run id it carries ("" if none)
  std::string restart_run_id;
  std::string restart_mesh_sha256;   // resume: the mesh the restart file's run wrote ("" if not recorded)
  int descriptors_needed = 12;       // file descriptors the run opens at once beyond those open now
};

/// The folder, held: the lock and the manifest now in it (already written).
struct FolderClaim {
  std::unique_ptr<OutputLock> lock;
  OutputManifest manifest;
  std::vector<std::string> removed;      // the earlier run's files removed (fresh run)
  std::vector<std::string> kept_inputs;  // the earlier run's files kept because the deck reads them
};

/// The files a run writes into its folder: log.txt, history.csv, history_columns.csv, summary.json
/// (+ .tmp); results.h5 + results.xdmf (+ .tmp) when `xdmf`; results.exo (+ .results.exo.partial)
/// when `exodus`; restart_K.h5 (+ .part) for K < ring_size, restart.h5 (+ .link) when ring_size > 0.
/// `ranks` > 1 with exodus: the per-rank files results.exo.N.r (and their rewrite copies) in place of results.exo.
std::vector<std::string> planned_output_names(bool xdmf, bool exodus, int ring_size, int ranks = 1);

/// Every check first, then the changes (README.md "The output folder"): path lengths (PATH_MAX,
/// NAME_MAX) and free file descriptors; the folder made if missing; the lock; the earlier manifest
/// read; a resumed run must continue its own run's folder (the restart file's run id = the
/// manifest's, and the same mesh) or a folder without outputs; a file this run would write that is
/// not the earlier run's, or that the deck reads, is refused. Any refusal is a SetupError with the
/// folder as it was (a folder made here is removed again). Then a fresh run removes the earlier
/// run's files (those still what it wrote; never one the deck reads), and the new manifest is written.
FolderClaim claim_output_folder(const FolderRequest& request);

/// After the outputs are open: the device and inode of every file of the manifest that exists now
/// (history.csv, history_columns.csv and results.exo are recognised by them), written.
void record_written_files(const std::filesystem::path& folder, OutputManifest& manifest);

/// SetupError when a file path in `folder` would exceed PATH_MAX or a component NAME_MAX.
void check_path_lengths(const std::filesystem::path& folder, const std::vector<std::string>& names);
/// SetupError ("too many open files (ulimit -n ...)") when `needed` more descriptors cannot be opened.
void check_free_descriptors(int needed);

}  // namespace tribex::solver
