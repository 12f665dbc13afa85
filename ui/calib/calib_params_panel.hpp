#pragma once
// The parameter panels of the calibration and radiometry workspaces: every widget generated from
// a row of calibSchema() / radiometrySchema() (ui/schema_form.hpp), the usual rows in titled
// groups and every other row under "Advanced", so no parameter is out of reach. Each widget
// changes only its own parameter; paramsChanged is emitted on every accepted edit. A change the
// workspace's controller refuses (a rule between steps) is shown with refuse().
#include <QWidget>
#include <memory>
#include <type_traits>

#include "core/calib/calib_params.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "ui/kit/params_command.hpp"
#include "ui/kit/schema_form.hpp"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QVBoxLayout;

namespace lwb::ui {

class CalibParamsPanel : public QWidget {
    Q_OBJECT
public:
    explicit CalibParamsPanel(QWidget* parent = nullptr);
    ~CalibParamsPanel() override;
    const core::calib::CalibParams& params() const { return m_form->params(); }
    /// Shows p without emitting paramsChanged.
    void setParams(const core::calib::CalibParams& p);
    /// Shows p again and "Not applied: why" (an edit the controller refused).
    void refuse(const core::calib::CalibParams& p, const QString& why);
    SchemaForm<core::calib::CalibParams>& form() { return *m_form; }
    /// The number field of a Real/Integer row, the combo box of a Choice row (tests).
    QDoubleSpinBox* field(const std::string& key) const;
    QComboBox* combo(const std::string& key) const;
    QLabel* messageLabel() const { return m_message; }

signals:
    void paramsChanged(const core::calib::CalibParams& p);

private:
    void updateEnabled();
    std::unique_ptr<SchemaForm<core::calib::CalibParams>> m_form;
    QLabel* m_message;
};

class RadiometryParamsPanel : public QWidget {
    Q_OBJECT
public:
    explicit RadiometryParamsPanel(QWidget* parent = nullptr);
    ~RadiometryParamsPanel() override;
    const core::radiometry::RadiometryParams& params() const { return m_form->params(); }
    /// Shows p without emitting paramsChanged.
    void setParams(const core::radiometry::RadiometryParams& p);
    /// Shows p again and "Not applied: why" (an edit the controller refused).
    void refuse(const core::radiometry::RadiometryParams& p, const QString& why);
    SchemaForm<core::radiometry::RadiometryParams>& form() { return *m_form; }
    QDoubleSpinBox* field(const std::string& key) const;
    QComboBox* combo(const std::string& key) const;
    QLabel* messageLabel() const { return m_message; }
    /// The "Row mosaic" group, for the workspace's line on the current mosaic.
    QFormLayout* mosaicGroup() const { return m_mosaic; }

signals:
    void paramsChanged(const core::radiometry::RadiometryParams& p);

private:
    std::unique_ptr<SchemaForm<core::radiometry::RadiometryParams>> m_form;
    QLabel* m_message;
    QFormLayout* m_mosaic;
};

/// Joins a parameter panel to its workspace's controller: an accepted edit becomes the
/// controller's parameters and a step of the workspace's undo history (ui/kit/params_command.hpp:
/// successive edits of one field merge; undo and redo put the panel and the controller back), and
/// the workspace emits `modified`; an edit the controller refuses (a rule between steps) is shown
/// on the panel and in the workspace's `status`, and is no step (issue 42: the calibration and
/// radiometry stacks were never pushed to).
template <class Panel, class Controller, class W>
void bindParamsPanel(Panel* panel, Controller* controller, W* workspace, const QString& what) {
    using Params = std::decay_t<decltype(controller->params())>;
    QObject::connect(panel, &Panel::paramsChanged, workspace, [=](const Params& p) {
        const Params before = controller->params();
        QString err;
        if (!controller->setParams(p, &err)) {
            panel->refuse(controller->params(), err);
            emit workspace->status(err);
            return;
        }
        pushParamsChange<Params>(
            workspace, panel->form().schema(), before, p,
            [=](const Params& q) {
                panel->setParams(q);
                controller->setParams(q, nullptr);
                emit workspace->modified();
            },
            what);
        emit workspace->modified();
    });
}

}  // namespace lwb::ui
