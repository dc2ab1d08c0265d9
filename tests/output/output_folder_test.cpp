// SPDX-License-Identifier: MIT
// The output folder a run owns (solver/output/output_folder.hpp, README.md "The output folder"): the
// lock, the manifest, what counts as a file the run wrote, and a refused claim leaving the folder as it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "solver/errors.hpp"
#include "solver/output/exodus_rank_file.hpp"
#include "solver/output/output_folder.hpp"

namespace fs = std::filesystem;
using namespace tribex::solver;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribex_folder_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::set<std::string> listing(const fs::path& d) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(d)) names.insert(e.path().filename().string());
  return names;
}

OutputManifest sample_identity() {
  return {new_run_id(), "deck \"a\".i", "", "0123abcd", "2026-11-28T00:00:00Z", "vm", {}, {}};
}

}  // namespace

TEST(OutputManifest, RoundTripsAndRefusesAForeignFile) {
  OutputManifest m = sample_identity();
  m.files = {{"log.txt", 0, 0}, {"history.csv", 65024, 123456789012ULL}};
  const OutputManifest back = parse_manifest(manifest_json(m), "x");
  EXPECT_EQ(back.run_id, m.run_id);
  EXPECT_EQ(back.deck, m.deck);  // the quotes escaped and read back
  ASSERT_EQ(back.files.size(), 2u);
  EXPECT_EQ(back.files[1].inode, 123456789012ULL);
  EXPECT_EQ(m.run_id.size(), 32u);
  EXPECT_NE(new_run_id(), new_run_id());
  EXPECT_THROW(parse_manifest("{\"format\": \"x\"}", "x"), SetupError);
  EXPECT_THROW(parse_manifest(manifest_json(m) + "junk", "x"), SetupError);
  std::string escaping = manifest_json(m);
  escaping.replace(escaping.find("history.csv"), 11, "../etc/pass");  // never a path outside the folder
  EXPECT_THROW(parse_manifest(escaping, "x"), SetupError);
}

// The run's segments (tribex join stitches a run resumed on another rank count by them): the restart time
// read back as the same double, and a manifest without the key (before 2026-11-29) has none.
TEST(OutputManifest, SegmentsRoundTripBitwise) {
  OutputManifest m = sample_identity();
  m.segments = {{2, 0.0}, {4, 3.4109335306355996e-12}, {3, 1.0 / 3.0}};
  const OutputManifest back = parse_manifest(manifest_json(m), "x");
  ASSERT_EQ(back.segments.size(), 3u);
  EXPECT_EQ(back.segments[1].ranks, 4);
  EXPECT_EQ(back.segments[1].from_time, 3.4109335306355996e-12);
  EXPECT_EQ(back.segments[2].from_time, 1.0 / 3.0);
  std::string old = manifest_json(sample_identity());
  old.erase(old.find(",\n  \"segments\""), std::string(",\n  \"segments\": [\n  ]").size());
  EXPECT_TRUE(parse_manifest(old, "x").segments.empty());
  std::string bad = manifest_json(m);
  bad.replace(bad.find("\"ranks\": 4"), 11, "\"ranks\": 0");
  EXPECT_THROW(parse_manifest(bad, "x"), SetupError);
}

TEST(OutputLock, RefusesASecondHolderNamingTheFirstAndIsGoneAfterRelease) {
  const fs::path d = fresh_dir("lock");
  {
    OutputLock first(d, "pid 1 on host vm, started T, run R");
    EXPECT_TRUE(first.stale_holder().empty());
    try {
      OutputLock second(d, "pid 2");
      FAIL() << "a second lock was granted";
    } catch (const SetupError& e) {
      EXPECT_NE(std::string(e.what()).find("in use by another tribex run (pid 1 on host vm, started T, run R)"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(d / OutputLock::file_name));
  // A lock file no process holds (its run was killed): taken over, its holder reported.
  write(d / OutputLock::file_name, "pid 99 on host gone\n");
  OutputLock again(d, "pid 3");
  EXPECT_EQ(again.stale_holder(), "pid 99 on host gone");
}

TEST(OutputManifest, WrittenByRunChecksTheIdentityAndTheFileKind) {
  const fs::path d = fresh_dir("written");
  const std::string id = new_run_id();
  write(d / "log.txt", "tribex 0.1 | run " + id + " | deck x.i\nmore\n");
  EXPECT_TRUE(written_by_run(d, {"log.txt"}, id));
  EXPECT_FALSE(written_by_run(d, {"log.txt"}, new_run_id()));
  write(d / "summary.json", "{\n  \"run_id\": \"" + id + "\",\n}\n");
  EXPECT_TRUE(written_by_run(d, {"summary.json"}, id));
  write(d / "history.csv", "step,time\n");
  EXPECT_FALSE(written_by_run(d, {"history.csv"}, id));  // no inode recorded
  OutputManifest m = sample_identity();
  m.add("history.csv");
  record_written_files(d, m);
  EXPECT_TRUE(written_by_run(d, *m.find("history.csv"), id));
  fs::remove(d / "history.csv");
  write(d / "other.csv", "x\n");
  fs::create_symlink("other.csv", d / "history.csv");
  EXPECT_FALSE(written_by_run(d, *m.find("history.csv"), id));  // a link is never the run's file
  write(d / "results.h5", "not hdf5");
  EXPECT_FALSE(written_by_run(d, {"results.h5"}, id));
}

TEST(OutputFolder, ARefusedClaimLeavesTheFolderAsItWas) {
  const fs::path d = fresh_dir("claim");
  write(d / "log.txt", "the user's notes\n");
  FolderRequest r;
  r.folder = d;
  r.names = planned_output_names(true, false, 2);
  r.identity = sample_identity();
  const auto before = listing(d);
  try {
    claim_output_folder(r);
    FAIL() << "a folder with the user's log.txt was claimed";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("holds log.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(listing(d), before);
  // A folder that is not there is made; the claim's lock is released with the claim.
  const fs::path made = d / "new" / "deeper";
  r.folder = made;
  EXPECT_NO_THROW(claim_output_folder(r));
  EXPECT_TRUE(fs::exists(made / manifest_file_name));
  EXPECT_FALSE(fs::exists(made / OutputLock::file_name));
  fs::remove(d / "log.txt");
  r.resume = true;  // a resumed run whose restart file carries another run id than the folder's
  r.folder = d;
  r.inputs.clear();
  OutputManifest theirs = sample_identity();
  write_manifest(d, theirs);
  r.restart_run_id = new_run_id();
  r.restart_path = "S/restart.h5";
  EXPECT_THROW(claim_output_folder(r), SetupError);
  r.folder = d / "fresh";
  EXPECT_NO_THROW(claim_output_folder(r));  // into a new folder: new files
}

// A parallel run with results.exo plans one file per rank (and its restart rewrite's copy), named as epu and
// nem_spread name them, in place of results.exo; the copies go by name as the run's temporaries.
TEST(OutputFolder, ParallelExodusPlansOneFilePerRank) {
  EXPECT_EQ(output::rank_file_name(16, 3), "results.exo.16.03");
  EXPECT_EQ(output::rank_file_name(2, 1), "results.exo.2.1");
  EXPECT_EQ(output::rank_file_name(100, 7), "results.exo.100.007");
  const auto serial = planned_output_names(false, true, 0, 1);
  const auto parallel = planned_output_names(false, true, 0, 4);
  const std::set<std::string> s(serial.begin(), serial.end()), p(parallel.begin(), parallel.end());
  EXPECT_TRUE(s.count("results.exo") && s.count(".results.exo.partial"));
  EXPECT_FALSE(p.count("results.exo"));
  for (int r = 0; r < 4; ++r) {
    EXPECT_TRUE(p.count("results.exo.4." + std::to_string(r))) << r;
    EXPECT_TRUE(p.count(".results.exo.4." + std::to_string(r) + ".partial")) << r;
  }
  EXPECT_EQ(parallel.size(), serial.size() + 6);  // 4 files and 4 copies for 1 and 1
  const fs::path dir = fs::temp_directory_path() / ("tribex_plan_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / ".results.exo.4.2.partial") << "x";
  EXPECT_TRUE(written_by_run(dir, {".results.exo.4.2.partial", 0, 0}, "any"));
  fs::remove_all(dir);
}
