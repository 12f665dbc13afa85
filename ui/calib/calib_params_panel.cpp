#include "ui/calib/calib_params_panel.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QVBoxLayout>

#include "ui/kit/param_slider.hpp"

namespace lwb::ui {

using core::calib::CalibModel;
using core::calib::CalibParams;
using core::calib::NoiseSource;
using core::radiometry::RadiometryParams;

namespace {

QFormLayout* addGroup(QVBoxLayout* box, QWidget* parent, const QString& title) {
    auto* g = new QGroupBox(title, parent);
    auto* f = new QFormLayout(g);
    f->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    box->addWidget(g);
    return f;
}

// "Advanced": every row not placed in a group; then the refused-edit message.
template <class P>
QLabel* finishPanel(SchemaForm<P>& form, QVBoxLayout* top, QWidget* owner, std::function<void()> changed) {
    auto* advanced = new CollapsibleSection(QObject::tr("Advanced (every other parameter)"), owner);
    form.addRemaining(advanced->form());
    top->addWidget(advanced);
    QLabel* message = form.addMessageLabel(std::move(changed));
    top->addWidget(message);
    return message;
}

template <class P>
QDoubleSpinBox* numberField(const SchemaForm<P>& form, const std::string& key) {
    auto* s = qobject_cast<ParamSlider*>(form.widget(key));
    return s ? s->field() : nullptr;
}

}  // namespace

// ---- calibration ----------------------------------------------------------------------------

CalibParamsPanel::~CalibParamsPanel() = default;

CalibParamsPanel::CalibParamsPanel(QWidget* parent)
    : QWidget(parent), m_form(std::make_unique<SchemaForm<CalibParams>>(core::calib::calibSchema(), this)) {
    SchemaForm<CalibParams>& form = *m_form;
    auto* top = new QVBoxLayout(this);
    top->setContentsMargins(0, 0, 0, 0);
    QFormLayout* det = addGroup(top, this, tr("Detector surface fit (paper 002 §3.2.3)"));
    form.add("detector.model", tr("Surface"),
             {tr("Auto (elliptical from 10 measured detectors)"), tr("Elliptical (7 parameters)"), tr("Circular (5 parameters)")});
    form.place(det, "detector.model");
    form.place(det, "detector.fit_background", tr("Fit the background"));
    form.place(det, "detector.background", tr("Fixed background"));
    form.place(det, "detector.trigger", tr("Trigger threshold"));
    form.place(det, "detector.saturation", tr("Saturation level"));
    form.add("detector.noise", tr("Noise"), {tr("Estimated from the array"), tr("Given below")});
    form.place(det, "detector.noise");
    form.place(det, "detector.rel_noise", tr("Relative noise"));
    form.place(det, "detector.noise_floor", tr("Noise floor"));
    form.place(det, "detector.scale_chi2", tr("Scale the covariance by χ²/dof"));
    QFormLayout* pt = addGroup(top, this, tr("Pointing && range calibration (eq. 2–5)"));
    form.add("pointing.model", tr("Model"), {tr("Single beam (each on its own)"), tr("Dual beam (eq. 3)")});
    form.place(pt, "pointing.model");
    form.place(pt, "pointing.solve_range", tr("Solve the range biases Δρ"));
    form.place(pt, "pointing.fix_relative", tr("Rigid beams (relative rotation fixed)"));
    form.place(pt, "pointing.sigma_h", tr("σ horizontal"));
    form.place(pt, "pointing.sigma_v", tr("σ vertical"));
    form.place(pt, "pointing.sigma_range", tr("σ range"));
    form.place(pt, "pointing.sigma_attitude_urad", tr("σ attitude"));
    form.place(pt, "pointing.sigma_orbit", tr("σ orbit"));
    form.place(pt, "pointing.scale_chi2", tr("Scale the covariance by χ²/dof"));
    QFormLayout* wf = addGroup(top, this, tr("Waveform and feature match (eq. 1)"));
    form.place(wf, "waveform.thred_h", tr("thred_h"));
    form.place(wf, "waveform.incidence_deg", tr("Incidence θ"));
    form.place(wf, "waveform.smooth_ns", tr("Peak-search smoothing"));
    form.place(wf, "waveform.min_separation_ns", tr("Min. separation"));
    form.place(wf, "waveform.sample_interval_ns", tr("Sample interval"));
    // Rigid beams belong to the dual model (calib::validate): leaving it releases them.
    form.adjust = [](const std::string& key, CalibParams& p) {
        if (key == "pointing.model" && p.pointing.model != CalibModel::DualBeam) p.pointing.fixRelativeRotation = false;
    };
    m_message = finishPanel(form, top, this, [this] {
        updateEnabled();
        emit paramsChanged(m_form->params());
    });
    updateEnabled();
}

void CalibParamsPanel::setParams(const CalibParams& p) {
    m_form->setParams(p);
    updateEnabled();
}

void CalibParamsPanel::refuse(const CalibParams& p, const QString& why) {
    setParams(p);
    if (m_form->onRefused) m_form->onRefused(why);
}

// Rows that have no effect with the others as they are: greyed, still showing their value.
void CalibParamsPanel::updateEnabled() {
    const CalibParams& p = m_form->params();
    const bool given = p.detector.noise == NoiseSource::Given;
    m_form->widget("detector.background")->setEnabled(!p.detector.fitBackground);
    m_form->widget("detector.rel_noise")->setEnabled(given);
    m_form->widget("detector.noise_floor")->setEnabled(given);
    m_form->widget("pointing.fix_relative")
        ->setEnabled(p.pointing.model == CalibModel::DualBeam || p.pointing.fixRelativeRotation);
}

QDoubleSpinBox* CalibParamsPanel::field(const std::string& key) const { return numberField(*m_form, key); }
QComboBox* CalibParamsPanel::combo(const std::string& key) const { return qobject_cast<QComboBox*>(m_form->widget(key)); }

// ---- radiometry -----------------------------------------------------------------------------

RadiometryParamsPanel::~RadiometryParamsPanel() = default;

RadiometryParamsPanel::RadiometryParamsPanel(QWidget* parent)
    : QWidget(parent), m_form(std::make_unique<SchemaForm<RadiometryParams>>(core::radiometry::radiometrySchema(), this)) {
    SchemaForm<RadiometryParams>& form = *m_form;
    auto* top = new QVBoxLayout(this);
    top->setContentsMargins(0, 0, 0, 0);
    QFormLayout* fit = addGroup(top, this, tr("Fit and uncertainty (eq. 5–6)"));
    form.place(fit, "dn_min", tr("Linear DN min"));
    form.place(fit, "dn_max", tr("Linear DN max"));
    form.place(fit, "exclude_out_of_range", tr("Leave regions outside the range out"));
    form.place(fit, "vm_pct", tr("V_M"));
    QFormLayout* img = addGroup(top, this, tr("Reflectance image and check"));
    form.place(img, "nan_out_of_range", tr("Pixels outside the range → NaN"));
    form.place(img, "uncertainty_image", tr("Per-pixel uncertainty image"));
    form.place(img, "limit_pct", tr("Error limit"));
    m_mosaic = addGroup(top, this, tr("Row mosaic (§3.1)"));
    form.add("mosaic.features", tr("Keypoints"), {tr("ORB (faster)"), tr("AKAZE (sub-pixel)")});
    form.place(m_mosaic, "mosaic.features");
    form.add("mosaic.model", tr("Motion"), {tr("Translation"), tr("Similarity"), tr("Affine"), tr("Homography")});
    form.place(m_mosaic, "mosaic.model");
    form.add("mosaic.blend", tr("Blend"), {tr("Feather"), tr("Average"), tr("First frame wins")});
    form.place(m_mosaic, "mosaic.blend");
    form.place(m_mosaic, "mosaic.ransac_px", tr("RANSAC"));
    m_message = finishPanel(form, top, this, [this] { emit paramsChanged(m_form->params()); });
}

void RadiometryParamsPanel::setParams(const RadiometryParams& p) { m_form->setParams(p); }

void RadiometryParamsPanel::refuse(const RadiometryParams& p, const QString& why) {
    setParams(p);
    if (m_form->onRefused) m_form->onRefused(why);
}

QDoubleSpinBox* RadiometryParamsPanel::field(const std::string& key) const { return numberField(*m_form, key); }
QComboBox* RadiometryParamsPanel::combo(const std::string& key) const {
    return qobject_cast<QComboBox*>(m_form->widget(key));
}

}  // namespace lwb::ui
