// The Events dock: the event log in words; choosing an event seeks there.
#pragma once

#include "core/frame.h"

#include <QWidget>
#include <memory>
#include <vector>

class QListWidget;

namespace jlui {

QString eventInWords(const jl::Event& e);

class EventsPanel : public QWidget {
    Q_OBJECT
public:
    explicit EventsPanel(QWidget* parent = nullptr);
    void setEvents(std::shared_ptr<const std::vector<jl::Event>> events);

signals:
    void seekRequested(double time);

private:
    QListWidget* list_;
    std::shared_ptr<const std::vector<jl::Event>> events_;
};

}  // namespace jlui
