#include "ui/workspace_layout.hpp"

#include <QHBoxLayout>
#include <QScrollArea>
#include <QSplitter>
#include <QVBoxLayout>

namespace lwb::ui {

void layoutWorkspace(QWidget* workspace, QLayout* top, QWidget* info, QWidget* body, QWidget* panel,
                     int panelMinWidth, int centreWidth) {
    auto* scroll = new QScrollArea(workspace);
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setMinimumWidth(panelMinWidth);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* centre = new QWidget(workspace);
    auto* cl = new QVBoxLayout(centre);
    cl->setContentsMargins(0, 0, 0, 0);
    cl->addLayout(top);
    cl->addWidget(info);
    cl->addWidget(body, 1);
    auto* split = new QSplitter(Qt::Horizontal, workspace);
    split->addWidget(centre);
    split->addWidget(scroll);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setSizes({centreWidth, panelMinWidth + 10});
    auto* lay = new QHBoxLayout(workspace);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->addWidget(split);
}

}  // namespace lwb::ui
