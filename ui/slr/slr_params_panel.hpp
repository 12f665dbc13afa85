#pragma once
// The SLR workspace's parameter panel: the screening (paper 004) and post-fit parameters, every
// widget generated from a row of slrSchema() (ui/schema_form.hpp); the rows not placed in the
// two groups are in the "Advanced" section, so every parameter can be reached. Each widget
// changes only its own parameter, with one exception the user asks for by name: the
// "automatic" switch turns the scale, area limit and connectivity to auto when switched on, and
// starts from the scale the last run chose when switched off.
#include <QWidget>
#include <memory>

#include "core/slr/slr_params.hpp"
#include "ui/kit/schema_form.hpp"

class QCheckBox;
class QLabel;

namespace lwb::ui {

class ParamSlider;
class CollapsibleSection;

class SlrParamsPanel : public QWidget {
    Q_OBJECT
public:
    explicit SlrParamsPanel(QWidget* parent = nullptr);
    ~SlrParamsPanel() override;
    const core::slr::SlrParams& params() const { return m_form->params(); }
    /// Shows p without emitting paramsChanged.
    void setParams(const core::slr::SlrParams& p);
    /// The scale a run used: shown on the fields left at auto, and the start when the automatic
    /// mode is switched off.
    void showScale(const core::slr::ScaleChoice& scale);
    /// What the post-fit's automatic values came to in a run (bin length, split gap, points a
    /// bin needs): shown on those fields while they are left automatic.
    void showPostfit(const core::slr::PostfitResult& post);

    SchemaForm<core::slr::SlrParams>& form() { return *m_form; }
    ParamSlider* slider(const std::string& key) const;
    QCheckBox* autoCheck() const;
    CollapsibleSection* advanced() const { return m_advanced; }
    QLabel* messageLabel() const { return m_message; }

signals:
    void paramsChanged(const core::slr::SlrParams& p);

private:
    std::unique_ptr<SchemaForm<core::slr::SlrParams>> m_form;
    CollapsibleSection* m_advanced;
    QLabel* m_message;
    core::slr::ScaleChoice m_scale;
    bool m_haveScale = false;
};

}  // namespace lwb::ui
