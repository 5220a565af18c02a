#include "core/package/scenario_package.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <set>
#include <sstream>

#include "core/atomic_replace.h"
#include "core/error.h"
#include "core/json_numbers.h"
#include "core/package/hydrometra_file.h"
#include "core/package/package_manifest.h"
#include "core/package/vtk_mesh_io.h"
#include "core/package/zip_archive.h"
#include "core/scenario/scenario_json.h"
#include "core/sha256.h"

namespace viscera::core {
namespace {

namespace fs = std::filesystem;

constexpr ZipLimits kLimits{kMaxZipEntryBytes, kMaxPackageBytes};

bool is_zip_path(const fs::path& path) {
  return path.extension() == ".vscz";
}

/// A unique hidden sibling name "<base>.tmp-<pid>-<n>". Never part of the output.
fs::path temporary_sibling(const fs::path& target) {
  return staging_sibling(target, ".tmp-");
}

/// A folder that is removed when it goes out of scope, whatever happened.
class ScratchFolder {
 public:
  explicit ScratchFolder(fs::path path) : path_(std::move(path)) { fs::create_directories(path_); }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open file", {path.string(), "", ""});
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_file(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw OutputError("cannot write file", {path.string(), "", ""});
}

/// Replaces `target` by `staged` (a file or folder) so that at every moment, a crash included,
/// either the old or the new package exists under the target name, never a mix; staging left
/// by writers that were killed goes first.
void move_into_place(const fs::path& staged, const fs::path& target) {
  replace_atomically(staged, target);
  remove_abandoned_staging(target);
}

/// Writes the package's files into `folder` and returns the manifest.
nlohmann::json write_package_files(const Scenario& scenario,
                                   const std::map<std::string, std::string>& extra_files,
                                   const fs::path& folder, Progress& progress) {
  progress.begin_stage("writing package",
                       static_cast<std::int64_t>(scenario.objects.size() + extra_files.size()) + 1);
  nlohmann::json files = nlohmann::json::object();
  const auto record = [&](const std::string& relative) {
    const fs::path path = folder / relative;
    files[relative] = {{"sha256", sha256_file(path)}, {"bytes", fs::file_size(path)}};
  };
  for (const auto& object : scenario.objects) {
    fs::create_directories(folder / "objects" / object.id);
    write_surface_vtp(object.surface, object.embedding, folder / surface_file_of(object.id));
    record(surface_file_of(object.id));
    if (object.body_kind != BodyKind::None) {
      write_body_vtu(object.body, folder / body_file_of(object.id));
      record(body_file_of(object.id));
    }
    if (!object.hydrometra.empty()) {
      write_file(folder / hydrometra_file_of(object.id), hydrometra_bytes(object.hydrometra));
      record(hydrometra_file_of(object.id));
    }
    progress.step();
  }
  for (const auto& [relative, bytes] : extra_files) {
    write_file(folder / relative, bytes);
    record(relative);
    progress.step();
  }
  return {{"format", kPackageFormat},
          {"version", kPackageVersion},
          {"scenario", scenario_to_json(scenario)},
          {"files", files}};
}

/// Checks the meshes against each other and the scenario: embeddings inside their bodies and
/// connections naming existing nodes.
std::vector<PackageIssue> check_meshes(const Scenario& scenario) {
  std::vector<PackageIssue> issues;
  for (std::size_t i = 0; i < scenario.objects.size(); ++i) {
    const auto& o = scenario.objects[i];
    for (std::size_t v = 0; v < o.embedding.tet.size(); ++v) {
      const int tet = o.embedding.tet[v];
      if (tet < 0 || tet >= static_cast<int>(o.body.tets.size())) {
        issues.push_back({surface_file_of(o.id), "",
                          "vertex " + std::to_string(v) + " is embedded in tet " +
                              std::to_string(tet) + ", which the body does not have"});
        break;
      }
    }
    if (!o.embedding.empty() && o.embedding.tet.size() != o.surface.vertices.size()) {
      issues.push_back({surface_file_of(o.id), "", "embedding does not cover every vertex"});
    }
    if (!o.hydrometra.empty() && o.hydrometra.node_count != static_cast<int>(o.body.nodes.size())) {
      issues.push_back({hydrometra_file_of(o.id), "",
                        "hydrometra states have " + std::to_string(o.hydrometra.node_count) +
                            " nodes, the body " + std::to_string(o.body.nodes.size())});
    }
    if (o.body_kind == BodyKind::TetMesh && o.body.tets.empty()) {
      issues.push_back({kManifestFile, "/scenario/objects/" + std::to_string(i),
                        "tet-mesh body has no tetrahedra"});
    }
  }
  for (std::size_t c = 0; c < scenario.connections.size(); ++c) {
    const auto& connection = scenario.connections[c];
    const SceneObject* a = scenario.find_object(connection.object_a);
    const SceneObject* b = scenario.find_object(connection.object_b);
    if (a == nullptr || b == nullptr) continue;  // reported by the reference check
    for (std::size_t p = 0; p < connection.node_pairs.size(); ++p) {
      const auto& pair = connection.node_pairs[p];
      if (pair[0] >= static_cast<int>(a->body.nodes.size()) ||
          pair[1] >= static_cast<int>(b->body.nodes.size())) {
        issues.push_back(
            {kManifestFile,
             "/scenario/connections/" + std::to_string(c) + "/node_pairs/" + std::to_string(p),
             "node pair refers to a node the bodies do not have"});
      }
    }
  }
  return issues;
}

/// Everything read from a package folder, with the problems found on the way.
struct Inspection {
  nlohmann::json manifest;
  Scenario scenario;
  std::vector<PackageIssue> issues;
};

/// Reads and checks a package folder. Throws InputError when it cannot be opened at all
/// (no manifest, invalid JSON, wrong format, newer version); every other problem is an issue.
Inspection inspect_folder(const fs::path& folder, const std::string& shown_name, bool stop_at_first,
                          Progress& progress) {
  Inspection result;
  const fs::path manifest_path = folder / kManifestFile;
  const std::string manifest_name = shown_name + "/" + kManifestFile;
  if (!fs::is_regular_file(manifest_path))
    throw InputError("package has no manifest.json", {shown_name, "", ""});
  result.manifest = parse_manifest(read_file(manifest_path), manifest_name);
  check_format_and_migrate(result.manifest, manifest_name);

  const auto stop = [&] { return stop_at_first && !result.issues.empty(); };
  result.issues = check_manifest_schema(result.manifest);
  if (!result.issues.empty()) return result;  // the checks below rely on the schema's shape
  result.issues = check_manifest_references(result.manifest);
  if (stop()) return result;

  // Checksums: every listed file exists and matches; nothing unlisted hides in the package.
  const auto& files = result.manifest.at("files");
  progress.begin_stage("checking package files", static_cast<std::int64_t>(files.size()));
  std::set<std::string> listed;
  for (const auto& [relative, entry] : files.items()) {
    listed.insert(relative);
    const fs::path path = folder / relative;
    if (!fs::is_regular_file(path)) {
      result.issues.push_back({relative, "", "file listed in the manifest is missing"});
    } else if (sha256_file(path) != entry.at("sha256").get<std::string>()) {
      result.issues.push_back(
          {relative, "", "checksum differs from the manifest (file changed or corrupt)"});
    }
    progress.step();
    if (stop()) return result;
  }
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), folder).generic_string();
    if (relative != kManifestFile && !listed.contains(relative)) {
      result.issues.push_back({relative, "", "file is not listed in the manifest"});
    }
  }
  if (!result.issues.empty()) return result;

  try {
    result.scenario = scenario_from_json(result.manifest.at("scenario"), manifest_name);
  } catch (const ValidationError& e) {
    result.issues.push_back({kManifestFile, e.location().json_pointer, e.reason()});
    return result;
  }
  const auto& objects = result.manifest.at("scenario").at("objects");
  progress.begin_stage("reading meshes", static_cast<std::int64_t>(objects.size()));
  for (std::size_t i = 0; i < objects.size(); ++i) {
    auto& object = result.scenario.objects[i];
    const std::string surface = objects[i].at("surface").get<std::string>();
    try {
      read_surface_vtp(folder / surface, object.surface, object.embedding);
      if (objects[i].contains("body"))
        object.body = read_body_vtu(folder / objects[i].at("body").get<std::string>());
      if (objects[i].contains("hydrometra")) {
        const std::string file = objects[i].at("hydrometra").get<std::string>();
        object.hydrometra = read_hydrometra_bytes(read_file(folder / file), file);
      }
    } catch (const InputError& e) {
      result.issues.push_back({surface, "", e.what()});
      if (stop()) return result;
    }
    progress.step();
  }
  auto mesh_issues = check_meshes(result.scenario);
  result.issues.insert(result.issues.end(), mesh_issues.begin(), mesh_issues.end());
  return result;
}

/// Runs `work` on the package as a folder: the folder itself, or a .vscz unpacked into a
/// scratch folder that is removed afterwards.
template <typename Work>
auto with_package_folder(const fs::path& path, Work&& work) {
  if (fs::is_directory(path)) return work(path);
  if (!fs::exists(path)) throw InputError("no such package", {path.string(), "", ""});
  const ScratchFolder scratch(
      fs::temp_directory_path() /
      ("viscera-" + std::to_string(getpid()) + "-" + temporary_sibling(path).filename().string()));
  unzip_to_folder(path, scratch.path(), kLimits);
  return work(scratch.path());
}

[[noreturn]] void throw_issue(const std::string& package, const PackageIssue& issue) {
  throw ValidationError(issue.message, {package + "/" + issue.file, issue.json_pointer, ""});
}

}  // namespace

void write_package(const Scenario& scenario, const fs::path& path, Progress& progress) {
  write_package(scenario, {}, path, progress);
}

void write_package(const Scenario& scenario, const std::map<std::string, std::string>& extra_files,
                   const fs::path& path, Progress& progress) {
  for (const auto& object : scenario.objects) {
    check_surface_mesh(object.surface, "object " + object.id + " surface");
    if (object.body_kind != BodyKind::None)
      check_tet_mesh(object.body, "object " + object.id + " body");
  }
  const fs::path staged = temporary_sibling(path);
  try {
    const ScratchFolder folder(is_zip_path(path) ? temporary_sibling(path.string() + "-folder")
                                                 : staged);
    nlohmann::json manifest = write_package_files(scenario, extra_files, folder.path(), progress);
    // The package must be readable by the same rules that will read it back.
    std::vector<PackageIssue> issues = check_manifest_schema(manifest);
    if (issues.empty()) issues = check_manifest_references(manifest);
    if (issues.empty()) issues = check_meshes(scenario);
    if (!issues.empty()) throw_issue(path.string(), issues.front());
    write_file(folder.path() / kManifestFile, manifest.dump(2) + "\n");
    if (is_zip_path(path)) {
      zip_folder(folder.path(), staged);
      move_into_place(staged, path);
    } else {
      move_into_place(folder.path(), path);
    }
  } catch (const Error&) {
    std::error_code ignored;
    fs::remove_all(staged, ignored);
    throw;
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove_all(staged, ignored);
    throw OutputError(std::string("cannot write the package: ") + e.what(),
                      {path.string(), "", ""});
  }
}

Scenario read_package(const fs::path& path, Progress& progress) {
  return with_package_folder(path, [&](const fs::path& folder) {
    Inspection inspection = inspect_folder(folder, path.string(), true, progress);
    if (!inspection.issues.empty()) throw_issue(path.string(), inspection.issues.front());
    return std::move(inspection.scenario);
  });
}

std::vector<PackageIssue> validate_package(const fs::path& path) {
  return with_package_folder(path, [&](const fs::path& folder) {
    return inspect_folder(folder, path.string(), false, Progress::none()).issues;
  });
}

PackageSummary summarize_package(const fs::path& path) {
  const std::string manifest_name = path.string() + "/" + kManifestFile;
  std::string text;
  if (fs::is_directory(path)) {
    if (!fs::is_regular_file(path / kManifestFile))
      throw InputError("package has no manifest.json", {path.string(), "", ""});
    text = read_file(path / kManifestFile);
  } else if (fs::exists(path)) {
    text = read_zip_entry(path, kManifestFile, kLimits);
  } else {
    throw InputError("no such package", {path.string(), "", ""});
  }
  nlohmann::json manifest = parse_manifest(text, manifest_name);
  check_format_and_migrate(manifest, manifest_name);
  const auto schema_issues = check_manifest_schema(manifest);
  if (!schema_issues.empty()) throw_issue(path.string(), schema_issues.front());

  PackageSummary summary;
  summary.format = manifest.at("format").get<std::string>();
  summary.version = whole_number<int>(manifest.at("version"), path.string(), "/version");
  const auto& scenario = manifest.at("scenario");
  summary.name = scenario.at("metadata").at("name").get<std::string>();
  summary.procedure = scenario.at("procedure").get<std::string>();
  const auto provenance = scenario.value("provenance", nlohmann::json::object());
  summary.template_name = provenance.value("template", std::string());
  if (provenance.contains("seed"))
    summary.seed =
        whole_number<std::uint64_t>(provenance["seed"], path.string(), "/scenario/provenance/seed");
  summary.object_count = static_cast<int>(scenario.at("objects").size());
  for (const auto& [relative, entry] : manifest.at("files").items()) {
    ++summary.file_count;
    summary.total_bytes += whole_number<std::uint64_t>(entry.at("bytes"), path.string(),
                                                       "/files/" + relative + "/bytes");
  }
  // Mesh sizes need the meshes: read them only for the counts.
  const Scenario loaded = read_package(path);
  for (const auto& object : loaded.objects) {
    summary.surface_triangles += static_cast<std::int64_t>(object.surface.triangles.size());
    summary.body_nodes += static_cast<std::int64_t>(object.body.nodes.size());
    summary.body_tets += static_cast<std::int64_t>(object.body.tets.size());
  }
  return summary;
}

void pack_package(const fs::path& folder, const fs::path& vscz) {
  if (!fs::is_directory(folder))
    throw InputError("not a package folder", {folder.string(), "", ""});
  const auto issues = inspect_folder(folder, folder.string(), true, Progress::none()).issues;
  if (!issues.empty()) throw_issue(folder.string(), issues.front());
  const fs::path staged = temporary_sibling(vscz);
  try {
    zip_folder(folder, staged);
    move_into_place(staged, vscz);
  } catch (...) {
    std::error_code ignored;
    fs::remove(staged, ignored);
    throw;
  }
}

void unpack_package(const fs::path& vscz, const fs::path& folder) {
  if (!fs::is_regular_file(vscz))
    throw InputError("no such package archive", {vscz.string(), "", ""});
  const fs::path staged = temporary_sibling(folder);
  try {
    fs::create_directories(staged);
    unzip_to_folder(vscz, staged, kLimits);
    const auto issues = inspect_folder(staged, vscz.string(), true, Progress::none()).issues;
    if (!issues.empty()) throw_issue(vscz.string(), issues.front());
    move_into_place(staged, folder);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staged, ignored);
    throw;
  }
}

}  // namespace viscera::core
