// The studio's document without widgets: open, edit through undoable commands, save, reopen,
// autosave and recovery (issue 9 §1).

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/materials/shipped_materials.h"
#include "core/package/scenario_package.h"
#include "studio/document/autosave.h"
#include "studio/document/document_commands.h"
#include "studio/document/primitive_objects.h"
#include "studio/document/scenario_document.h"
#include "templates/template_catalog.h"

namespace fs = std::filesystem;
using namespace viscera;

class DocumentTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path ball_package_;

  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

 private slots:
  void initTestCase() {
    QVERIFY(tmp_.isValid());
    ball_package_ = dir() / "ball.vscene";
    const core::Scenario scenario =
        templates::build_from_template("ball", {{"cell_size", "0.012"}}, 1);
    core::write_package(scenario, ball_package_);
  }

  void opensCleanAndNamesTheFile() {
    studio::ScenarioDocument document;
    QSignalSpy changed(&document, &studio::ScenarioDocument::changed);
    document.open(ball_package_);
    QCOMPARE(changed.count(), 1);
    QVERIFY(!document.is_dirty());
    QCOMPARE(document.display_name(), QString("ball.vscene"));
    QCOMPARE(document.scenario().objects.size(), std::size_t{1});
    QCOMPARE(document.scenario().objects[0].id, std::string("ball"));
  }

  void everyEditUndoesAndRedoes() {
    studio::ScenarioDocument document;
    document.open(ball_package_);
    const core::Scenario original = document.scenario();

    studio::PrimitiveRequest request;
    request.center = core::Vec3(0.1, 0.0, 0.0);
    request.size = 0.015;
    request.cell_size = 0.008;
    const core::Material myometrium = core::shipped_material("myometrium");
    const std::string id = studio::unique_object_id(document.scenario(), "ball");
    QCOMPARE(id, std::string("ball-2"));
    core::SceneObject ball = studio::build_primitive_object(request, id, myometrium);
    QVERIFY(ball.body.tets.size() > 100);
    QCOMPARE(ball.embedding.tet.size(), ball.surface.vertices.size());
    const core::BoundingBox box = core::bounds(ball.surface);
    QVERIFY(std::abs(box.max.x() - 0.115) < 1e-3);

    auto* stack = document.undo_stack();
    stack->push(new studio::AddObjectCommand(document, ball, myometrium));
    QVERIFY(document.is_dirty());
    QCOMPARE(document.scenario().objects.size(), std::size_t{2});
    QVERIFY(document.scenario().materials.contains("myometrium"));
    const core::Scenario after_add = document.scenario();

    stack->push(
        new studio::AssignMaterialCommand(document, "ball", core::shipped_material("liver")));
    QCOMPARE(document.scenario().find_object("ball")->material, std::string("liver"));
    const core::Scenario after_assign = document.scenario();

    stack->push(
        new studio::EditMaterialCommand(document, "liver", studio::MaterialField::Density, 1234.0));
    stack->push(
        new studio::EditMaterialCommand(document, "liver", studio::MaterialField::Density, 1250.0));
    QCOMPARE(stack->count(), 3);  // the two density edits merged
    QCOMPARE(document.scenario().materials.at("liver").density, 1250.0);
    const core::Scenario after_edit = document.scenario();

    stack->undo();
    QVERIFY(document.scenario() == after_assign);
    stack->undo();
    QVERIFY(document.scenario() == after_add);
    stack->undo();
    QVERIFY(document.scenario() == original);
    QVERIFY(!document.is_dirty());
    stack->redo();
    stack->redo();
    stack->redo();
    QVERIFY(document.scenario() == after_edit);
    QVERIFY(document.is_dirty());

    const fs::path saved = dir() / "edited.vscz";
    document.save_as(saved);
    QVERIFY(!document.is_dirty());
    QCOMPARE(document.display_name(), QString("edited.vscz"));
    studio::ScenarioDocument reopened;
    reopened.open(saved);
    QVERIFY(reopened.scenario() == after_edit);
  }

  void badEditsAndBadFilesKeepTheDocument() {
    studio::ScenarioDocument document;
    document.open(ball_package_);
    const core::Scenario before = document.scenario();
    QVERIFY_EXCEPTION_THROWN(
        studio::EditMaterialCommand(document, "soft-tissue", studio::MaterialField::Density, -1.0),
        core::UsageError);
    QVERIFY_EXCEPTION_THROWN(studio::RemoveObjectCommand(document, "nothing"), core::UsageError);
    const fs::path broken = dir() / "broken.vscene";
    fs::create_directories(broken);
    {
      std::ofstream out(broken / "manifest.json");
      out << "{ \"format\": ";
    }
    QVERIFY_EXCEPTION_THROWN(document.open(broken), core::InputError);
    QVERIFY(document.scenario() == before);
    QCOMPARE(document.path(), ball_package_);
    QVERIFY(!document.is_dirty());
  }

  void autosavesWhileDirtyAndOffersRecovery() {
    studio::ScenarioDocument document;
    document.open(ball_package_);
    const fs::path recovery = dir() / "recovery";
    studio::Autosave autosave(document, recovery, 50);
    QSignalSpy saved(&autosave, &studio::Autosave::autosaved);
    QVERIFY(!saved.wait(300));  // clean: nothing to save
    QVERIFY(!studio::Autosave::find_recovery(recovery));

    document.undo_stack()->push(new studio::RemoveObjectCommand(document, "ball"));
    QVERIFY(saved.wait(5000));
    const auto copy = studio::Autosave::find_recovery(recovery);
    QVERIFY(copy.has_value());
    QCOMPARE(copy->original_path, ball_package_);
    QVERIFY(copy->written.isValid());
    QVERIFY(std::abs(copy->written.secsTo(QDateTime::currentDateTimeUtc())) < 60);
    studio::ScenarioDocument recovered;
    recovered.reset(studio::read_document_content(copy->package), copy->original_path);
    QVERIFY(recovered.scenario() == document.scenario());
    QVERIFY(recovered.is_dirty());

    document.save_as(dir() / "after-recovery.vscene");
    autosave.wait();
    QVERIFY(!studio::Autosave::find_recovery(recovery));
  }
};

QTEST_MAIN(DocumentTest)
#include "document_test.moc"
