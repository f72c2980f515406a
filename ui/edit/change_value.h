// One undo command for "change a value of the scene": get/set of a field, a
// merge id, and a command that drops itself when the net change is zero.
#pragma once

#include "ui/edit/document.h"

#include <QUndoCommand>

#include <chrono>
#include <functional>

namespace jl::ui {

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
        : QUndoCommand(text),
          doc_(doc),
          field_(std::move(field)),
          old_(field_.get(doc->scene())),
          new_(std::move(value)),
          last_(std::chrono::steady_clock::now()) {}

    void redo() override { apply(new_); }
    void undo() override { apply(old_); }
    int id() const override { return int(field_.id); }
    // One gesture (arrow clicks, a slider or a mouse drag) sends its values
    // within a fraction of a second of each other and is one step of the
    // history; an edit of the same field a moment later is a step of its own.
    static constexpr std::chrono::milliseconds kGesture{800};
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = dynamic_cast<const ChangeValue*>(other);
        if (!o || o->field_.key != field_.key || o->last_ - last_ > kGesture) return false;
        last_ = o->last_;
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
    std::chrono::steady_clock::time_point last_;  // when the last value of the gesture came
};

// Pushes a change unless it changes nothing.
template <typename T>
void changeScene(Document* doc, const SceneField<T>& field, T value, const QString& text) {
    if (field.get(doc->scene()) == value) return;
    doc->undoStack()->push(new ChangeValue<T>(doc, field, std::move(value), text));
}

}  // namespace jl::ui
