#include "ui/edit/document.h"

#include "jl/scene/scene_io.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

#include <numbers>

namespace jl::ui {

namespace {
constexpr int kAutosaveMs = 30'000;
constexpr const char* kRecoveredFromTag = "# recovered-from: ";
}  // namespace

Document::Document(QObject* parent) : QObject(parent) {
    scene_ = newScene();
    connect(&undo_, &QUndoStack::cleanChanged, this, [this](bool clean) {
        emit modifiedChanged(!clean);
        if (clean) removeRecovery();
    });
    autosave_.setInterval(kAutosaveMs);
    connect(&autosave_, &QTimer::timeout, this, [this] {
        if (isModified()) writeRecovery();
    });
    autosave_.start();
}

// The undo stack, cleared as it is destroyed, reports itself clean: that is
// not a save, so the recovery copy must not go with it.
Document::~Document() { disconnect(&undo_, nullptr, this, nullptr); }

jl::Scene Document::newScene() {
    jl::Scene s;
    s.title = "New ladder";
    s.ladder = jl::LadderSpec{};
    jl::ScriptAction turn;
    turn.kind = jl::ScriptAction::Kind::Turn;
    turn.at = 0.2;
    turn.block = 0;
    // Counter-clockwise, as in the classic cascade: the way that folds hinge 1
    // and sends the ripple down (the other way only throws the ladder about).
    turn.angle = std::numbers::pi;
    turn.duration = 0.3;
    s.script.push_back(turn);
    s.duration = 2.5;
    return s;
}

QString Document::displayName() const { return path_.isEmpty() ? tr("Untitled") : QFileInfo(path_).fileName(); }

void Document::reset(const jl::Scene& scene, const QString& path, bool modified) {
    scene_ = scene;
    path_ = path;
    undo_.clear();
    if (modified)
        undo_.resetClean();  // no clean state reachable: it is unsaved work
    else
        undo_.setClean();
    emit modifiedChanged(modified);
    emit pathChanged(path_);
    emit changed(SceneChange::Whole);
}

std::vector<jl::Diagnostic> Document::open(const QString& path) {
    jl::SceneLoad load = jl::loadScene(path.toStdString());
    if (!load.scene) {
        if (load.errors.empty()) load.errors.push_back({path.toStdString(), 0, 0, "could not be read"});
        return load.errors;
    }
    reset(*load.scene, QFileInfo(path).absoluteFilePath());
    return {};
}

std::optional<QString> Document::saveAs(const QString& path) {
    if (auto err = jl::saveScene(scene_, path.toStdString())) return QString::fromStdString(err->format());
    path_ = QFileInfo(path).absoluteFilePath();
    undo_.setClean();
    emit pathChanged(path_);
    return std::nullopt;
}

QString Document::recoveryPath() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QDir(dir).filePath("recovery.yaml");
}

// The scene as a scene file, with the original path on a comment line so
// the recovered copy can be saved back where it came from.
void Document::writeRecovery() const {
    const QString file = recoveryPath();
    QDir().mkpath(QFileInfo(file).absolutePath());
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly)) return;
    out.write(QByteArray(kRecoveredFromTag) + path_.toUtf8() + "\n");
    out.write(QByteArray::fromStdString(jl::sceneToYaml(scene_)));
    out.commit();
}

void Document::removeRecovery() { QFile::remove(recoveryPath()); }

}  // namespace jl::ui
