// One undo command for "change a value of the scene": get/set of a field, a
// merge id, and a command that drops itself when the net change is zero.
#pragma once

#include "ui/document.h"

#include <QUndoCommand>
#include <functional>

namespace jlui {

template <typename T>
struct SceneField {
    UndoId id;
    QString key;  // commands merge only when id and key agree
    SceneChange change;
    std::function<T(const jl::Scene&)> get;
    std::function<void(jl::Scene&, const T&)> set;
};

template <typename T>
class ChangeValue : public QUndoCommand {
public:
    ChangeValue(Document* doc, SceneField<T> field, T value, const QString& text)
        : QUndoCommand(text), doc_(doc), field_(std::move(field)), old_(field_.get(doc->scene())), new_(std::move(value)) {}

    void redo() override { apply(new_); }
    void undo() override { apply(old_); }
    int id() const override { return int(field_.id); }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = dynamic_cast<const ChangeValue*>(other);
        if (!o || o->field_.key != field_.key) return false;
        new_ = o->new_;
        setObsolete(new_ == old_);
        return true;
    }

private:
    void apply(const T& v) {
        field_.set(doc_->editableScene(), v);
        doc_->notifyChanged(field_.change);
    }
    Document* doc_;
    SceneField<T> field_;
    T old_, new_;
};

// Pushes a change unless it changes nothing.
template <typename T>
void changeScene(Document* doc, const SceneField<T>& field, T value, const QString& text) {
    if (field.get(doc->scene()) == value) return;
    doc->undoStack()->push(new ChangeValue<T>(doc, field, std::move(value), text));
}

}  // namespace jlui
