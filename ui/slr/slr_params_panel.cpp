#include "ui/slr/slr_params_panel.hpp"

#include <QDoubleSpinBox>
#include <algorithm>

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace lwb::ui {

using namespace core::slr;

SlrParamsPanel::~SlrParamsPanel() = default;

SlrParamsPanel::SlrParamsPanel(QWidget* parent)
    : QWidget(parent), m_form(std::make_unique<SchemaForm<SlrParams>>(slrSchema(), this)) {
    SchemaForm<SlrParams>& form = *m_form;
    auto* top = new QVBoxLayout(this);
    top->setContentsMargins(0, 0, 0, 0);
    auto* sg = new QGroupBox(tr("Screening (binary image)"), this);
    auto* sf = new QFormLayout(sg);
    form.place(sf, "screen.automatic", tr("Automatic scale, area limit and connectivity"));
    form.place(sf, "screen.mag_t", tr("mag_T"));
    form.place(sf, "screen.mag_oc", tr("mag_OC"));
    form.place(sf, "screen.area_limit", tr("Area limit"));
    sf->addRow(tr("Connectivity"), form.addValues("screen.connectivity", {{4, tr("4-connectivity")}, {8, tr("8-connectivity")}}));
    form.place(sf, "screen.cosine_c", tr("Cosine C"));
    top->addWidget(sg);
    auto* pg = new QGroupBox(tr("Post-fit and normal points"), this);
    auto* pf = new QFormLayout(pg);
    form.place(pf, "postfit.reject_sigma", tr("Rejection (k σ)"));
    // (the largest degree tried when the degree is chosen per segment, the default: the legend
    // gives the one chosen, "trend (deg 5, max 10)")
    form.place(pf, "postfit.degree", tr("Trend degree ≤"));
    top->addWidget(pg);
    m_advanced = new CollapsibleSection(tr("Advanced (every other parameter)"), this);
    form.addRemaining(m_advanced->form());
    top->addWidget(m_advanced);
    m_message = form.addMessageLabel([this] { emit paramsChanged(m_form->params()); });
    top->addWidget(m_message);

    form.adjust = [this](const std::string& key, SlrParams& p) {
        if (key != "screen.automatic") return;
        ScreenParams& s = p.screen;
        if (s.automatic) {  // on: the scale, area limit and connectivity are chosen again
            s.magT = s.magOc = 0;
            s.areaLimit = s.connectivity = 0;
        } else if (m_haveScale) {  // off: from what the automatic mode chose last
            if (s.magT == 0) s.magT = m_scale.magT;
            if (s.magOc == 0) s.magOc = m_scale.magOc;
            if (s.areaLimit == 0) s.areaLimit = m_scale.areaLimit;
            if (s.connectivity == 0) s.connectivity = m_scale.connectivity;
        }
    };
    // The scale fields hold values like 1.23457e+10 px/s: wide enough for the number and its unit.
    for (const char* key : {"screen.mag_t", "screen.mag_oc"})
        if (ParamSlider* sl = slider(key)) {
            QDoubleSpinBox* f = sl->field();
            const int w = f->fontMetrics().horizontalAdvance("-1.23457e+10" + f->suffix()) + 40;
            f->setMinimumWidth(w);
            f->setMaximumWidth(std::max(w, f->maximumWidth()));
        }
    setParams(SlrParams{});
}

void SlrParamsPanel::setParams(const SlrParams& p) {
    m_form->setParams(p);
    m_message->hide();
}

void SlrParamsPanel::showScale(const ScaleChoice& scale) {
    m_scale = scale;
    m_haveScale = scale.magT > 0 && scale.magOc > 0 && scale.areaLimit > 0 && scale.connectivity > 0;
    // Shown to 6 significant digits (the field would show every digit and push the unit out);
    // switching the automatic mode off starts from the exact values (m_scale).
    auto six = [](double v) { return QString::number(v, 'g', 6).toDouble(); };
    m_form->setHint("screen.mag_t", six(scale.magT));
    m_form->setHint("screen.mag_oc", six(scale.magOc));
    m_form->setHint("screen.area_limit", scale.areaLimit);
    m_form->setHint("screen.connectivity", scale.connectivity);
}

void SlrParamsPanel::showPostfit(const PostfitResult& post) {
    // What "auto", "from altitude" and "ILRS minimum" came to in the last run (the disabled
    // field showed its slider's middle, "153 s", where the run's bins were 30 s).
    const bool ok = post.ok;
    m_form->setHint("postfit.bin_length_s", ok && post.binLengthS > 0 ? post.binLengthS : NAN);
    m_form->setHint("postfit.split_gap_s", ok && post.splitGapS > 0 ? post.splitGapS : NAN);
    m_form->setHint("postfit.min_points", ok && post.minPointsPerBin > 0 ? post.minPointsPerBin : NAN);
}

ParamSlider* SlrParamsPanel::slider(const std::string& key) const { return qobject_cast<ParamSlider*>(m_form->widget(key)); }

QCheckBox* SlrParamsPanel::autoCheck() const { return qobject_cast<QCheckBox*>(m_form->widget("screen.automatic")); }

}  // namespace lwb::ui
