#include "ui/kit/modal_work.hpp"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QTimer>
#include <QWidget>
#include <algorithm>
#include <cmath>

namespace lwb::ui {

namespace {
std::atomic<int> gDialogsShown{0};
}

int ModalProgress::dialogsShown() { return gDialogsShown.load(); }

ModalProgress::ModalProgress(QWidget* parent, QString label)
    : m_parent(parent), m_label(std::move(label)), m_fb([this](double f) {
          if (std::isfinite(f)) m_permille.store(std::clamp(static_cast<int>(f * 1000.0), 0, 1000), std::memory_order_relaxed);
      }) {}

void ModalProgress::wait(const QFuture<void>& work) {
    if (work.isFinished()) return;
    QEventLoop loop;
    QFutureWatcher<void> watcher;
    QObject::connect(&watcher, &QFutureWatcher<void>::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(work);

    // First the window keeps painting while user input waits (a short load shows no dialog);
    // then the dialog, window-modal: the window behind it takes no input until the work ends.
    QTimer later;
    later.setSingleShot(true);
    QObject::connect(&later, &QTimer::timeout, &loop, &QEventLoop::quit);
    later.start(kShowAfterMs);
    loop.exec(QEventLoop::ExcludeUserInputEvents);
    if (work.isFinished()) return;

    QProgressDialog dialog(m_label, QCoreApplication::translate("lwb::ui::ModalProgress", "Cancel"), 0, 1000, m_parent);
    dialog.setWindowTitle(QCoreApplication::translate("lwb::ui::ModalProgress", "Working"));
    dialog.setObjectName("modalProgress");
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(0);
    dialog.setAutoClose(false);
    dialog.setAutoReset(false);
    QObject::connect(&dialog, &QProgressDialog::canceled, &dialog, [this, &dialog] {
        m_fb.cancel();
        dialog.setLabelText(QCoreApplication::translate("lwb::ui::ModalProgress", "Cancelling…"));
    });
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, &dialog, [this, &dialog] {
        if (dialog.wasCanceled() && !m_fb.isCancelled()) {  // (Escape, the window's close button, cancel())
            m_fb.cancel();
            dialog.setLabelText(QCoreApplication::translate("lwb::ui::ModalProgress", "Cancelling…"));
        }
        if (!m_fb.isCancelled()) dialog.setValue(m_permille.load(std::memory_order_relaxed));
    });
    tick.start(50);
    dialog.setValue(m_permille.load(std::memory_order_relaxed));
    dialog.show();
    gDialogsShown.fetch_add(1);
    if (!work.isFinished()) loop.exec();
    tick.stop();
    dialog.hide();
}

}  // namespace lwb::ui
