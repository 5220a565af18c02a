// `viscera generate` as a user runs it (issue 6 §4–5, issue 20 §4): a batch of validated
// hysteroscopy patients with its index; the same batch under `mpirun -n 2` (patients handed out
// dynamically), as shards plus --merge and killed half way then restarted, equal to the
// single-process run byte for byte.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::run_program;
using testing::shell_quote;

/// Every regular file under `folder`, by path relative to it, with its bytes.
std::map<std::string, std::string> all_files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), folder).generic_string()] =
          viscera::testing::file_bytes(entry.path());
  }
  return files;
}

/// Asserts that two batch folders hold the same files with the same bytes.
void expect_same_files(const fs::path& a, const fs::path& b) {
  const auto fa = all_files(a), fb = all_files(b);
  ASSERT_FALSE(fa.empty());
  std::vector<std::string> names_a, names_b;
  for (const auto& [name, bytes] : fa)
    names_a.push_back(name);
  for (const auto& [name, bytes] : fb)
    names_b.push_back(name);
  ASSERT_EQ(names_a, names_b);
  for (const auto& [name, bytes] : fa)
    EXPECT_TRUE(bytes == fb.at(name)) << name << " differs";
}

std::string batch_arguments(int count, int seed, const fs::path& out) {
  return "generate --template hysteroscopy --count " + std::to_string(count) + " --seed " +
         std::to_string(seed) + " -o " + shell_quote(out.string());
}

/// A single-process batch, made once for all test processes (named after the build of
/// `viscera`, so a rebuilt program makes a new one).
fs::path reference_batch(int count, int seed) {
  const char* root = std::getenv("VISCERA_TEST_TMP");
  const fs::path shared_root =
      fs::path(root != nullptr ? root : fs::temp_directory_path().string()) / "real-files";
  fs::create_directories(shared_root);
  const auto built = fs::last_write_time(fs::path(VISCERA_BINARY_DIR) / "bin" / "viscera");
  const fs::path shared =
      shared_root / ("generate-hysteroscopy-" + std::to_string(count) + "-" + std::to_string(seed) +
                     "-" + std::to_string(built.time_since_epoch().count()));
  if (!fs::exists(shared)) {
    const fs::path work = shared_root / (".generate-" + std::to_string(::getpid()));
    fs::remove_all(work);
    fs::create_directories(work);
    const auto result = run_program("viscera", batch_arguments(count, seed, work / "batch"), work);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    std::error_code taken;  // another test process may have put its copy in place first
    fs::rename(work / "batch", shared, taken);
    fs::remove_all(work);
  }
  return shared;
}

/// `mpirun` with the flags this machine needs: more ranks than cores, and root in containers.
std::string mpirun(int ranks) {
  std::string command =
      std::string(VISCERA_MPIEXEC) + " --oversubscribe -n " + std::to_string(ranks);
  if (::geteuid() == 0) command += " --allow-run-as-root";
  return command;
}

TEST(GenerateCommand, writes_twenty_different_valid_hysteroscopy_patients_with_an_index) {
  const fs::path batch = reference_batch(20, 1);
  const nlohmann::json index =
      nlohmann::json::parse(viscera::testing::file_bytes(batch / "index.json"));
  EXPECT_EQ(index.at("format"), "viscera-generate-index");
  EXPECT_EQ(index.at("template"), "hysteroscopy");
  EXPECT_EQ(index.at("count"), 20);
  ASSERT_EQ(index.at("patients").size(), 20u);
  std::size_t redraws = 0;
  for (std::size_t k = 0; k < 20; ++k) {
    const auto& p = index.at("patients")[k];
    EXPECT_EQ(p.at("index"), k);
    EXPECT_TRUE(p.at("validation").at("valid").get<bool>()) << k;
    for (const char* check : {"surfaces", "overlap", "tets", "pathologies", "attachments",
                              "connections", "references", "simulation"})
      EXPECT_TRUE(p.at("validation").at("checks").at(check).at("passed").get<bool>()) << check;
    EXPECT_GE(p.at("validation").at("checks").at("tets").at("min_dihedral_degrees").get<double>(),
              index.at("validation_bounds").at("min_dihedral_degrees").get<double>());
    EXPECT_EQ(p.at("attempts").get<std::size_t>(), p.at("redraws").size() + 1);
    redraws += p.at("redraws").size();
    const fs::path package = batch / p.at("package").get<std::string>();
    const auto valid =
        run_program("viscera", "validate " + shell_quote(package.string()), testing::scratch_dir());
    EXPECT_EQ(valid.exit_code, 0) << package << valid.err;
  }
  EXPECT_EQ(index.at("redraws").at("total").get<std::size_t>(), redraws);
  // Different patients: every parameter set and every uterus shape differs.
  const auto& diversity = index.at("diversity");
  EXPECT_EQ(diversity.at("distinct_parameter_sets"), 20);
  EXPECT_EQ(diversity.at("shape_distance").at("pairs"), 190);
  EXPECT_EQ(diversity.at("shape_distance").at("identical_pairs"), 0);
  EXPECT_GT(diversity.at("shape_distance").at("min").get<double>(), 1e-4);
  int counted = 0;
  for (const int c : diversity.at("parameters").at("length").at("counts"))
    counted += c;
  EXPECT_EQ(counted, 20);
  // Only packages and the index: invalid draws are never written.
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(batch)) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 21u);
}

TEST(GenerateCommand, patient_k_depends_only_on_template_seed_and_k) {
  const fs::path large = reference_batch(20, 1), small = reference_batch(6, 1);
  for (int k = 0; k < 6; ++k) {
    const std::string name = "patient-000" + std::to_string(k) + ".vscene";
    expect_same_files(large / name, small / name);
  }
}

TEST(GenerateCommand, mpi_run_on_two_ranks_equals_the_single_process_run_byte_for_byte) {
  const fs::path reference = reference_batch(6, 1);
  const fs::path dir = testing::scratch_dir();
  const std::string command =
      mpirun(2) + " " + shell_quote((fs::path(VISCERA_BINARY_DIR) / "bin" / "viscera").string()) +
      " " + batch_arguments(6, 1, dir / "mpi") + " >" + shell_quote((dir / "mpi.log").string()) +
      " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << viscera::testing::file_bytes(dir / "mpi.log");
  expect_same_files(reference, dir / "mpi");
}

TEST(GenerateCommand, shard_runs_and_merge_equal_the_single_process_run_byte_for_byte) {
  const fs::path reference = reference_batch(6, 1);
  const fs::path dir = testing::scratch_dir();
  for (const char* shard : {"1/2", "0/2"}) {
    const auto result =
        run_program("viscera", batch_arguments(6, 1, dir / "sharded") + " --shard " + shard, dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  EXPECT_TRUE(fs::exists(dir / "sharded" / "index.shard-0-of-2.json"));
  EXPECT_FALSE(fs::exists(dir / "sharded" / "index.json"));
  const auto merged =
      run_program("viscera", "generate --merge " + shell_quote((dir / "sharded").string()), dir);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  expect_same_files(reference, dir / "sharded");
}

/// Journal entries (finished patients) of an interrupted batch in `folder`.
std::vector<fs::path> journal_entries(const fs::path& folder) {
  std::vector<fs::path> entries;
  std::error_code missing;
  for (const auto& e : fs::directory_iterator(folder / ".generate-journal", missing)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("patient-", 0) == 0 && e.path().extension() == ".json")
      entries.push_back(e.path());
  }
  return entries;
}

/// Inode of `path`: a package generated again is a new folder moved into place.
ino_t inode_of(const fs::path& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 ? status.st_ino : 0;
}

TEST(GenerateCommand, batch_killed_half_way_resumes_without_redoing_written_patients) {
  const fs::path reference = reference_batch(6, 1);
  const fs::path dir = testing::scratch_dir();
  const fs::path batch = dir / "batch";
  // The real program as a child of this test, killed (SIGKILL: no clean-up at all) once two
  // patients are journalled.
  const std::string program = (fs::path(VISCERA_BINARY_DIR) / "bin" / "viscera").string();
  std::vector<std::string> words = {program,   "generate",    "--template", "hysteroscopy",
                                    "--count", "6",           "--seed",     "1",
                                    "-o",      batch.string()};
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
  pid_t child = 0;
  ASSERT_EQ(posix_spawn(&child, program.c_str(), &quiet, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&quiet);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  int status = 0;
  bool exited = false;
  while (journal_entries(batch).size() < 2 && std::chrono::steady_clock::now() < give_up) {
    if (::waitpid(child, &status, WNOHANG) == child) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!exited) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  ASSERT_FALSE(exited) << "the batch ended before it could be interrupted";
  ASSERT_FALSE(fs::exists(batch / "index.json"));
  const auto finished = journal_entries(batch);
  ASSERT_GE(finished.size(), 2u);
  ASSERT_LT(finished.size(), 6u);
  std::map<std::string, ino_t> written;
  for (const auto& entry : finished) {
    const auto record = nlohmann::json::parse(viscera::testing::file_bytes(entry)).at("record");
    const std::string package = record.at("package").get<std::string>();
    written[package] = inode_of(batch / package);
  }
  // A finished patient whose package was damaged afterwards is generated again.
  const std::string damaged = written.begin()->first;
  {
    std::ofstream append(batch / damaged / "manifest.json", std::ios::app);
    append << " ";
  }
  // Restarted with the same arguments it finishes, keeping the other finished patients.
  const auto resumed = run_program("viscera", batch_arguments(6, 1, batch) + " --json", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto summary = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(summary.at("kept").get<std::size_t>(), written.size() - 1);
  EXPECT_EQ(summary.at("generated").get<std::size_t>(), 6 - (written.size() - 1));
  for (const auto& [package, inode] : written) {
    if (package == damaged) {
      EXPECT_NE(inode_of(batch / package), inode) << package << " was kept though damaged";
    } else {
      EXPECT_EQ(inode_of(batch / package), inode) << package << " was generated again";
    }
  }
  // No journal, no staging leftovers: the same bytes as an uninterrupted run.
  expect_same_files(reference, batch);
}

TEST(GenerateCommand, an_unfinished_batch_is_not_resumed_with_other_arguments) {
  const fs::path dir = testing::scratch_dir();
  const fs::path batch = dir / "b";
  // A shard leaves its journal until --merge: the folder holds an unfinished batch.
  ASSERT_EQ(run_program("viscera",
                        "generate --template ball --count 2 --seed 1 -o " +
                            shell_quote(batch.string()) + " --shard 0/2",
                        dir)
                .exit_code,
            0);
  const auto other = run_program(
      "viscera", "generate --template ball --count 2 --seed 2 -o " + shell_quote(batch.string()),
      dir);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("unfinished batch"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find(batch.string()), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(batch / "index.json"));
}

TEST(GenerateCommand, merge_refuses_a_missing_shard_and_bad_options_are_usage_errors) {
  const fs::path dir = testing::scratch_dir();
  const auto one = run_program("viscera",
                               "generate --template ball --count 2 --seed 1 -o " +
                                   shell_quote((dir / "b").string()) + " --shard 0/2",
                               dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto merged =
      run_program("viscera", "generate --merge " + shell_quote((dir / "b").string()), dir);
  EXPECT_EQ(merged.exit_code, 3);
  EXPECT_NE(merged.err.find("1 of 2 partial indexes"), std::string::npos) << merged.err;
  EXPECT_FALSE(fs::exists(dir / "b" / "index.json"));
  EXPECT_EQ(
      run_program("viscera", "generate --template ball --count 2 -o x --shard 2/2", dir).exit_code,
      2);
  EXPECT_EQ(run_program("viscera", "generate --template ball --count 0 -o x", dir).exit_code, 2);
  EXPECT_EQ(run_program("viscera", "generate --template nope --count 1 -o x", dir).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "x"));
}

}  // namespace
}  // namespace viscera

namespace viscera {
namespace {

TEST(TemplatesCommand, every_template_lists_its_parameters_and_builds_a_valid_package_at_defaults) {
  const fs::path dir = testing::scratch_dir();
  const auto listed = run_program("viscera", "templates --json", dir);
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  const nlohmann::json catalog = nlohmann::json::parse(listed.out);
  std::vector<std::string> names;
  for (const auto& t : catalog) {
    names.push_back(t.at("name"));
    ASSERT_FALSE(t.at("parameters").empty());
    for (const auto& p : t.at("parameters")) {
      EXPECT_FALSE(p.at("unit").get<std::string>().empty()) << p;
      EXPECT_LE(p.at("minimum").get<double>(), p.at("default").get<double>()) << p;
      EXPECT_LE(p.at("default").get<double>(), p.at("maximum").get<double>()) << p;
    }
    const fs::path package = dir / (names.back() + ".vscene");
    const auto made = run_program(
        "viscera", "new --template " + names.back() + " -o " + shell_quote(package.string()), dir);
    ASSERT_EQ(made.exit_code, 0) << names.back() << made.err;
    const auto valid = run_program("viscera", "validate " + shell_quote(package.string()), dir);
    EXPECT_EQ(valid.exit_code, 0) << names.back() << valid.err;
  }
  for (const char* expected :
       {"ball", "hysteroscopy", "laparoscopy-gyn", "urethra", "agent-tissue"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

}  // namespace
}  // namespace viscera
