#include "ui/slr/slr_strips.hpp"

#include <QCoreApplication>
#include <QSlider>
#include <QTimer>
#include <QtConcurrent>
#include <algorithm>
#include <cmath>

#include "core/slr/slr_params.hpp"
#include "ui/kit/param_slider.hpp"
#include "ui/slr/slr_controller.hpp"
#include "ui/slr/slr_params_panel.hpp"

namespace lwb::ui {

const std::vector<std::string>& SlrStrips::keys() {
    static const std::vector<std::string> k = {"postfit.reject_sigma", "screen.cosine_c", "screen.area_limit",
                                               "screen.mag_oc", "screen.mag_t"};
    return k;
}

SlrStrips::SlrStrips(SlrController* controller, SlrParamsPanel* panel, QObject* parent)
    : QObject(parent), m_controller(controller), m_panel(panel), m_timer(new QTimer(this)) {
    // After a run is shown, once the analyst has let go for a moment; a change of the parameters
    // or the edits makes the strips being computed stale (a new run comes).
    m_timer->setSingleShot(true);
    m_timer->setInterval(300);
    connect(m_timer, &QTimer::timeout, this, &SlrStrips::refresh);
    connect(controller, &SlrController::runReady, m_timer, qOverload<>(&QTimer::start));
    auto stale = [this] {
        m_timer->stop();
        if (m_work) m_work->cancel();
        m_done = true;
        // (drawn faint until the strips of the parameters of now replace them)
        for (const std::string& key : keys())
            if (ParamSlider* s = m_panel->slider(key)) s->setStripStale(true);
    };
    connect(controller, &SlrController::paramsSet, this, stale);
    connect(controller, &SlrController::editsChanged, this, stale);
    // A pass changed or a run that failed: no strip describes what is shown.
    auto clear = [this, stale] {
        stale();
        clearAll();
    };
    connect(controller, &SlrController::passChanged, this, clear);
    connect(controller, &SlrController::runFailed, this, clear);
}

SlrStrips::~SlrStrips() {
    if (m_work) m_work->cancel();
}

int SlrStrips::positions(const std::string& key) {
    const auto* f = core::slr::slrSchema().find(key);
    return f && f->stage >= core::slr::kStagePostfit ? kPositions : kScreenPositions;
}

SlrStrips::Drawn SlrStrips::drawn(const std::string& key) const {
    const auto it = m_drawn.find(key);
    return it == m_drawn.end() ? Drawn{} : it->second;
}

void SlrStrips::clearAll() {
    m_drawn.clear();
    for (const std::string& key : keys())
        if (ParamSlider* s = m_panel->slider(key)) s->clearStrip();
}

void SlrStrips::refresh() {
    if (m_controller->busy()) {  // (its run's delivery starts the timer again)
        m_timer->start();
        return;
    }
    if (m_work) m_work->cancel();
    if (!m_controller->hasPass() || !m_controller->hasRun()) {
        clearAll();
        m_work.reset();
        emit ready();
        return;
    }
    const long long points = static_cast<long long>(m_controller->pass().t.size());
    if (points > kMaxPoints) {
        m_drawn.clear();
        for (const std::string& key : keys())
            if (ParamSlider* s = m_panel->slider(key))
                s->setStrip({}, {}, tr("No strip on a pass of %1 points (strips are computed up to %2: each is the pass run "
                                       "again %3 times)")
                                        .arg(points)
                                        .arg(kMaxPoints)
                                        .arg(positions(key)));
        m_work.reset();
        emit ready();
        return;
    }
    auto work = std::make_shared<core::Feedback>();
    m_work = work;
    m_done = false;
    struct Strip {
        std::string key;
        QPointer<ParamSlider> slider;
        std::vector<double> values;
        std::vector<core::slr::SweepOutcome> outcomes;
    };
    auto strips = std::make_shared<std::vector<Strip>>();
    for (const std::string& key : keys())
        if (ParamSlider* s = m_panel->slider(key)) strips->push_back({key, s, s->trackValues(positions(key)), {}});
    auto base = std::make_shared<const SlrController::SweepBase>(m_controller->sweepBase());
    QPointer<SlrStrips> self(this);
    // Strip by strip, each drawn as soon as it is computed (the post-fit's first: it reuses the
    // screening and takes a fraction of a screening row's time).
    (void)QtConcurrent::run([self, work, strips, base] {
        for (Strip& s : *strips) {
            s.outcomes = core::slr::sweepSlrParam(base->setup, base->inputs, base->params, s.key, s.values, base->labels,
                                                  base->reuse, work.get());
            if (work->isCancelled()) return;
            QMetaObject::invokeMethod(qApp, [self, work, s, base] {
                if (self && !work->isCancelled() && self->m_work == work) self->draw(s.key, s.slider, s.values, s.outcomes, base->labelsName);
            });
        }
        QMetaObject::invokeMethod(qApp, [self, work] {
            if (!self || work->isCancelled() || self->m_work != work) return;
            self->m_done = true;
            emit self->ready();
        });
    });
}

void SlrStrips::draw(const std::string& key, ParamSlider* slider, const std::vector<double>& values,
                     const std::vector<core::slr::SweepOutcome>& outcomes, const QString& labelsName) {
    if (!slider) return;
    // The delivered points as the area (of the most along the track); F1 against the labels as
    // the line (over a span of at least 0.02, so that a wiggle of 0.001 is not drawn as a
    // cliff), else the post-fit's RMS (of the largest).
    long long most = 0;
    double rmsLo = INFINITY, rmsHi = 0, f1Lo = INFINITY, f1Hi = -INFINITY;
    size_t bestAt = 0;
    int failed = 0;
    for (size_t k = 0; k < outcomes.size(); ++k) {
        const core::slr::SweepOutcome& o = outcomes[k];
        if (!o.ok) {
            ++failed;
            continue;
        }
        most = std::max(most, o.delivered);
        if (std::isfinite(o.rmsS)) rmsLo = std::min(rmsLo, o.rmsS), rmsHi = std::max(rmsHi, o.rmsS);
        if (std::isfinite(o.f1)) {
            if (o.f1 > f1Hi) bestAt = k;
            f1Lo = std::min(f1Lo, o.f1), f1Hi = std::max(f1Hi, o.f1);
        }
    }
    std::vector<double> area, line;
    const bool f1 = std::isfinite(f1Hi);
    const double span = std::max(0.02, f1Hi - f1Lo);
    for (const core::slr::SweepOutcome& o : outcomes) {
        area.push_back(o.ok && most > 0 ? double(o.delivered) / double(most) : 0.0);
        if (f1) line.push_back(o.ok && std::isfinite(o.f1) ? (o.f1 - (f1Hi - span)) / span : 0.0);
        else if (rmsHi > 0) line.push_back(o.ok && std::isfinite(o.rmsS) ? o.rmsS / rmsHi : 0.0);
    }
    QString tip = tr("Strip: points kept along the slider (up to %1)").arg(most);
    const auto ps = [](double v) { return QString::number(v * 1e12, 'f', 1); };
    if (rmsHi > 0)
        tip += ps(rmsLo) == ps(rmsHi) ? tr("; post-fit RMS %1 ps all along").arg(ps(rmsHi))
                                      : tr("; post-fit RMS %1 to %2 ps").arg(ps(rmsLo), ps(rmsHi));
    const auto four = [](double v) { return QString::number(v, 'f', 4); };
    if (f1 && four(f1Lo) == four(f1Hi))
        tip += tr("; orange: F1 against %1, %2 all along").arg(labelsName, four(f1Hi));
    else if (f1)
        tip += tr("; orange: F1 against %1, %2 to %3 (best at %4)")
                   .arg(labelsName, four(f1Lo), four(f1Hi), QString::number(values[bestAt], 'g', 4));
    else if (rmsHi > 0)
        tip += tr("; orange: the RMS (no labels: the pass has no station flags)");
    if (failed > 0) tip += tr("; %1 of the %2 values give no run").arg(failed).arg(outcomes.size());
    slider->setStrip(std::move(area), std::move(line), tip);
    m_drawn[key] = {values, outcomes};
}

}  // namespace lwb::ui
