#include "ui/kit/frame_loader.hpp"

#include <QThread>
#include <QThreadPool>
#include <algorithm>

namespace lwb::ui {

int loaderThreadCount() { return std::max(1, QThread::idealThreadCount() - 1); }

QThreadPool* loaderPool() {
    static QThreadPool* pool = [] {
        auto* p = new QThreadPool();  // like qApp, lives until the process ends
        p->setMaxThreadCount(loaderThreadCount());
        return p;
    }();
    return pool;
}

}  // namespace lwb::ui
