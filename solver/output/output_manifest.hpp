// SPDX-License-Identifier: MIT
// OUT/.tribex_manifest.json: the run that owns an output folder and the files it writes there
// (README.md "The output folder"). A fresh run removes exactly the files of the earlier run's
// manifest that are still what that run wrote; a resumed run continues only its own run's folder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tribex::solver {

struct ManifestEntry {
  std::string name;                         // a plain file name inside the folder
  unsigned long long device = 0, inode = 0;  // of the file once written (0: not recorded)
};

/// One process's share of a run's steps: its rank count and the time it started from (a fresh run: its
/// start; a resumed run: the restart time, where it rewrote the results files from). `tribex join`
/// stitches per-rank results of several rank counts by these (solver/output/README.md "Restart on another
/// rank count").
struct RunSegment {
  int ranks = 1;
  double from_time = 0.0;
};

struct OutputManifest {
  std::string run_id;       // 32 hex digits, random; kept by the runs resumed from this run's restart files
  std::string deck;         // the deck as given on the command line
  std::string deck_sha256;  // of the deck file's bytes ("" if unknown)
  std::string mesh_sha256;  // of the mesh's coordinates and connectivity (solver/restart/run_fingerprint.hpp)
  std::string started;      // ISO 8601 UTC of the segment that wrote the manifest
  std::string host;
  std::vector<ManifestEntry> files;
  std::vector<RunSegment> segments;  // every process of the run, in order (absent in manifests before 2026-11-29)

  const ManifestEntry* find(const std::string& name) const;
  void add(const std::string& name);  // once
};

inline constexpr const char* manifest_file_name = ".tribex_manifest.json";

/// The folder's manifest; nullopt when there is none. SetupError (naming the file and the fix) when
/// it cannot be read or is not a manifest.
std::optional<OutputManifest> read_manifest(const std::filesystem::path& folder);
/// Writes it through a temporary file and a rename (a reader sees the old or the new one whole);
/// SetupError on failure.
void write_manifest(const std::filesystem::path& folder, const OutputManifest& manifest);
/// The manifest's JSON text, and back (SetupError naming `where` if it is not a manifest).
std::string manifest_json(const OutputManifest& m);
OutputManifest parse_manifest(const std::string& text, const std::string& where);

/// Is `folder/entry.name` still the file the run `run_id` wrote? A regular file only (a symbolic
/// link, FIFO, device or folder never is; links are not followed), and: results.h5 and restart
/// files carry the run id as an HDF5 attribute `run_id`, summary.json as its key `run_id`, log.txt
/// in its first line; history.csv, history_columns.csv, results.exo and results.exo.N.r must be the
/// recorded inode; the temporaries (*.tmp, *.part, *.link, .results.exo[.N.r].partial) and results.xdmf go by name.
bool written_by_run(const std::filesystem::path& folder, const ManifestEntry& entry, const std::string& run_id);

/// A new run id: 128 random bits as 32 hex digits.
std::string new_run_id();
/// The run id (HDF5 attribute `run_id`) of a restart or results file; "" when it has none.
std::string h5_run_id(const std::string& path);

}  // namespace tribex::solver
