// The scene's title and description (the lesson a teacher writes for a
// class), edited in a dialog and applied as one undoable change that leaves
// the simulation running as it was: words change no physics.
#pragma once

#include "jl/scene/load_limits.h"

#include <QDialog>

class QLineEdit;
class QPlainTextEdit;

namespace jl::ui {

class Document;

class SceneTextDialog : public QDialog {
    Q_OBJECT
public:
    SceneTextDialog(Document* doc, QWidget* parent = nullptr);
    QLineEdit* titleField() const { return title_; }
    QPlainTextEdit* descriptionField() const { return description_; }

    // What a scene file can hold: no control characters (a file with one
    // would not load), the title on one line; both within sane lengths.
    static QString cleanTitle(const QString& text);
    static QString cleanDescription(const QString& text);
    // The scene file's limits (a longer text would make a file that does not load).
    static constexpr int kLongestTitle = int(jl::kMostTitleCharacters);
    static constexpr int kLongestDescription = int(jl::kMostDescriptionCharacters);

    void accept() override;  // pushes the change if anything changed

private:
    Document* doc_;
    QLineEdit* title_;
    QPlainTextEdit* description_;
};

}  // namespace jl::ui
