#include "studio/document/scenario_document.h"

#include <algorithm>
#include <fstream>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "core/package/zip_archive.h"
#include "exporters/scenario_exporter.h"
#include "studio/document/model_objects.h"
#include "studio/document/view_state.h"

namespace viscera::studio {

DocumentContent read_document_content(const std::filesystem::path& path, core::Progress& progress) {
  DocumentContent content;
  content.scenario = core::read_package(path, progress);
  content.files = exporters::read_package_textures(path, content.scenario);
  content.files.merge(read_package_models(path, content.scenario));
  // The studio's view state (visibility, opacity), when the package has one.
  if (std::filesystem::is_directory(path)) {
    std::ifstream in(path / kViewStateFile, std::ios::binary);
    if (in) content.files[kViewStateFile].assign(std::istreambuf_iterator<char>(in), {});
  } else {
    const core::ZipLimits limits{core::kMaxZipEntryBytes, core::kMaxPackageBytes};
    const std::vector<std::string> entries = core::checked_zip_entries(path, limits);
    if (std::find(entries.begin(), entries.end(), kViewStateFile) != entries.end())
      content.files[kViewStateFile] = core::read_zip_entry(path, kViewStateFile, limits);
  }
  try {
    view_state_of(content.files);
  } catch (const core::InputError& e) {
    throw core::InputError(e.reason(),
                           {(path / kViewStateFile).string(), e.location().json_pointer, ""});
  }
  return content;
}

void write_document_content(const DocumentContent& content, const std::filesystem::path& path,
                            core::Progress& progress) {
  core::write_package(content.scenario, content.files, path, progress);
}

ScenarioDocument::ScenarioDocument(QObject* parent) : QObject(parent) {
  qRegisterMetaType<ChangeKind>("viscera::studio::ChangeKind");
  connect(&undo_stack_, &QUndoStack::cleanChanged, this, [this] { emit status_changed(); });
}

ScenarioDocument::~ScenarioDocument() {
  undo_stack_.disconnect(this);
  blockSignals(true);
}

QString ScenarioDocument::display_name() const {
  if (path_.empty()) return QStringLiteral("untitled");
  return QString::fromStdString(path_.filename().string());
}

void ScenarioDocument::reset(DocumentContent content, const std::filesystem::path& path,
                             bool unsaved) {
  undo_stack_.clear();
  content_ = std::move(content);
  path_ = path;
  unsaved_ = unsaved;
  undo_stack_.setClean();
  emit changed(ChangeKind::Everything, {});
  emit status_changed();
}

void ScenarioDocument::open(const std::filesystem::path& path, core::Progress& progress) {
  adopt_opened(read_document_content(path, progress), path);
}

void ScenarioDocument::adopt_opened(DocumentContent content, const std::filesystem::path& path) {
  reset(std::move(content), path, false);
}

void ScenarioDocument::save(core::Progress& progress) {
  if (path_.empty()) throw core::UsageError("the document has no file yet; use Save As");
  save_as(path_, progress);
}

void ScenarioDocument::save_as(const std::filesystem::path& path, core::Progress& progress) {
  write_document_content(content_, path, progress);
  mark_saved(path);
}

void ScenarioDocument::mark_saved(const std::filesystem::path& path) {
  path_ = path;
  unsaved_ = false;
  undo_stack_.setClean();
  emit status_changed();
}

void ScenarioDocument::notify_changed(ChangeKind kind, const QString& id) {
  emit changed(kind, id);
}

}  // namespace viscera::studio
