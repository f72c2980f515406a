#include "ui/edit/scene_text_dialog.h"

#include "ui/edit/document.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QUndoCommand>

namespace jl::ui {

namespace {

class ChangeSceneText : public QUndoCommand {
public:
    ChangeSceneText(Document* doc, std::string title, std::string description)
        : QUndoCommand(QObject::tr("Change the title and description")),
          doc_(doc),
          oldTitle_(doc->scene().title),
          oldDescription_(doc->scene().description),
          title_(std::move(title)),
          description_(std::move(description)) {}
    void redo() override { set(title_, description_); }
    void undo() override { set(oldTitle_, oldDescription_); }

private:
    void set(const std::string& title, const std::string& description) {
        doc_->editableScene().title = title;
        doc_->editableScene().description = description;
        doc_->notifyChanged(SceneChange::Text);
    }
    Document* doc_;
    std::string oldTitle_, oldDescription_, title_, description_;
};

QString withoutControls(const QString& text, bool keepNewlines) {
    QString out;
    for (QChar c : text) {
        if (c == '\n' && keepNewlines)
            out += c;
        else if (c == '\t')
            out += ' ';
        else if (c.category() != QChar::Other_Control && c.category() != QChar::Other_Format)
            out += c;
        else if (c == '\n' || c == '\r')
            out += ' ';
    }
    return out;
}

}  // namespace

QString SceneTextDialog::cleanTitle(const QString& text) {
    return withoutControls(text, false).simplified().left(kLongestTitle);
}

QString SceneTextDialog::cleanDescription(const QString& text) {
    return withoutControls(text, true).trimmed().left(kLongestDescription);
}

SceneTextDialog::SceneTextDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
    setObjectName("sceneTextDialog");
    setWindowTitle(tr("Title and description"));
    auto* form = new QFormLayout(this);
    title_ = new QLineEdit(QString::fromStdString(doc->scene().title), this);
    title_->setObjectName("titleField");
    title_->setMaxLength(kLongestTitle);
    description_ = new QPlainTextEdit(QString::fromStdString(doc->scene().description), this);
    description_->setObjectName("descriptionField");
    description_->setMinimumSize(460, 220);
    auto* hint = new QLabel(tr("The lesson panel shows them, and the Lessons menu lists the scene by its title. "
                               "An empty line starts a new paragraph."),
                            this);
    hint->setWordWrap(true);
    form->addRow(tr("&Title"), title_);
    form->addRow(tr("&Description"), description_);
    form->addRow(hint);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &SceneTextDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

void SceneTextDialog::accept() {
    const std::string title = cleanTitle(title_->text()).toStdString();
    const std::string description = cleanDescription(description_->toPlainText()).toStdString();
    if (title != doc_->scene().title || description != doc_->scene().description)
        doc_->undoStack()->push(new ChangeSceneText(doc_, title, description));
    QDialog::accept();
}

}  // namespace jl::ui
