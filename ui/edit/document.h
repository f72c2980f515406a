// One open scene: the Scene, its file, the modified flag and the undo stack;
// saves atomically and keeps a recovery copy while there are unsaved edits.
#pragma once

#include "jl/base/diagnostic.h"
#include "jl/scene/scene.h"
#include "ui/edit/scene_change.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <QUndoStack>

#include <optional>
#include <vector>

namespace jl::ui {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const jl::Scene& scene() const { return scene_; }
    QString path() const { return path_; }
    QString displayName() const;
    bool isModified() const { return !undo_.isClean(); }
    QUndoStack* undoStack() { return &undo_; }

    // A fresh ladder, an opened file, or a recovered one: forgets the undo history.
    void reset(const jl::Scene& scene, const QString& path, bool modified = false);
    // Loads a file; on errors nothing changes and every error is returned.
    std::vector<jl::Diagnostic> open(const QString& path);
    // Writes atomically; the error in words, or nothing.
    std::optional<QString> saveAs(const QString& path);

    // For undo commands only.
    jl::Scene& editableScene() { return scene_; }
    void notifyChanged(SceneChange c) { emit changed(c); }

    // The recovery copy: where it lives, writing it, and removing it once saved or closed.
    static QString recoveryPath();
    void writeRecovery() const;
    static void removeRecovery();

    static jl::Scene newScene();

signals:
    void changed(jl::ui::SceneChange change);
    void modifiedChanged(bool modified);
    void pathChanged(const QString& path);

private:
    jl::Scene scene_;
    QString path_;
    QUndoStack undo_;
    QTimer autosave_;
};

}  // namespace jl::ui
