#include "ui/events_panel.h"

#include <QListWidget>
#include <QVBoxLayout>

namespace jlui {

QString eventInWords(const jl::Event& e) {
    QString what = QString::fromStdString(e.text);
    if (what.isEmpty()) what = QObject::tr("hinge %1: %2").arg(e.hinge).arg(QString::fromUtf8(jl::toString(e.kind)));
    return QString("%1 s: %2").arg(e.time, 0, 'f', 3).arg(what);
}

EventsPanel::EventsPanel(QWidget* parent) : QWidget(parent) {
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    list_ = new QListWidget(this);
    list_->setObjectName("events");
    list_->setToolTip(tr("What happened at each hinge, in order; click one to see that moment."));
    list_->setUniformItemSizes(true);
    box->addWidget(list_);
    connect(list_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        emit seekRequested(item->data(Qt::UserRole).toDouble());
    });
}

void EventsPanel::setEvents(std::shared_ptr<const std::vector<jl::Event>> events) {
    if (events == events_) return;
    const size_t had = (events_ && events && events->size() >= events_->size()) ? events_->size() : 0;
    // The log only grows while playing: append; anything else rebuilds it.
    if (had == 0) list_->clear();
    events_ = std::move(events);
    if (!events_) return;
    for (size_t i = had; i < events_->size(); ++i) {
        auto* item = new QListWidgetItem(eventInWords((*events_)[i]), list_);
        item->setData(Qt::UserRole, (*events_)[i].time);
    }
    if (had < events_->size()) list_->scrollToBottom();
}

}  // namespace jlui
