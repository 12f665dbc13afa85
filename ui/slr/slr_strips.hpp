#pragma once
// The strips beside the SLR sliders (issue 45): for the sliders an analyst tunes a satellite
// with (the magnifications, the area limit, the cosine constant, the post-fit's rejection), the
// outcome of moving that slider alone to each of positions() places along its track, drawn under
// its groove (ParamSlider::setStrip) so that the plateau and the cliff are seen before the
// handle moves: the filled strip the points the run delivers, the line F1 against the labels
// where the pass has any (a simulation's truth, the station's filter flags), else the post-fit's
// RMS. Each value is the pass task as the rerun after that change would run it (core
// sweepSlrParam: the same resolution, the same stages reused). Computed in the background after
// every run, strip by strip (each drawn when it is ready), the work of the one before cancelled
// and its strips drawn faint until replaced;
// not on passes of more than kMaxPoints points (a tooltip says so): a screening slider's strip is
// the pass screened kScreenPositions times (the five strips: 2.6 s of the two cores on a
// 7 400-point pass).
#include <QObject>
#include <QPointer>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/tune.hpp"

class QTimer;

namespace lwb::ui {

class ParamSlider;
class SlrController;
class SlrParamsPanel;

class SlrStrips : public QObject {
    Q_OBJECT
public:
    static constexpr int kPositions = 24;        ///< along a post-fit slider (the screening reused)
    static constexpr int kScreenPositions = 12;  ///< along a screening slider (the pass screened each time)
    static constexpr long long kMaxPoints = 200000;
    /// The sliders with a strip, by schema key (the post-fit's first: the cheapest).
    static const std::vector<std::string>& keys();
    /// The values along `key`'s strip: kPositions on a post-fit row, kScreenPositions on a screening one.
    static int positions(const std::string& key);

    SlrStrips(SlrController* controller, SlrParamsPanel* panel, QObject* parent = nullptr);
    ~SlrStrips() override;
    /// Starts the strips' computation now (the controller idle; else once its run is delivered).
    void refresh();
    /// The strips are being computed.
    bool busy() const { return m_work && !m_done; }
    /// What the last strip of `key` was drawn from: the values along the track and each one's
    /// outcome (empty before the first, or when the strips were cleared or not computed).
    struct Drawn {
        std::vector<double> values;
        std::vector<core::slr::SweepOutcome> outcomes;
    };
    Drawn drawn(const std::string& key) const;

signals:
    /// Every strip of the last refresh is drawn (or cleared).
    void ready();

private:
    void clearAll();
    void draw(const std::string& key, ParamSlider* slider, const std::vector<double>& values,
              const std::vector<core::slr::SweepOutcome>& outcomes, const QString& labelsName);

    SlrController* m_controller;
    SlrParamsPanel* m_panel;
    QTimer* m_timer;
    std::shared_ptr<core::Feedback> m_work;  ///< the strips being computed (cancelled by the next)
    bool m_done = true;
    std::map<std::string, Drawn> m_drawn;
};

}  // namespace lwb::ui
