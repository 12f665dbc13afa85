#pragma once
// The workbench window: one tab per workspace, sessions (JSON, atomic saves, recent files,
// unsaved-changes prompt), settings, status bar, error dialogs.
#include <QJsonObject>
#include <QMainWindow>
#include <QMessageBox>
#include <functional>

class QTabWidget;
class QMenu;
class QProgressBar;
class QPushButton;

namespace lwb::ui {

class FootprintWorkspace;
class SlrWorkspace;
class CalibWorkspace;
class RadiometryWorkspace;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    FootprintWorkspace* footprint() const { return m_footprint; }
    SlrWorkspace* slr() const { return m_slr; }
    CalibWorkspace* calib() const { return m_calib; }
    RadiometryWorkspace* radiometry() const { return m_radiometry; }
    QTabWidget* tabs() const { return m_tabs; }

    /// Loads the built-in demo in every workspace (after the unsaved-changes prompt; false when
    /// the analyst cancelled it).
    bool openDemo();
    /// Opens footprint frames, folders or a shot list, replacing the list (after the
    /// unsaved-changes prompt; false when cancelled).
    bool openFootprintInputs(const QStringList& paths);
    /// Opens a session file (after the unsaved-changes prompt); on error shows a dialog (unless
    /// quiet) and keeps the current state.
    bool openSession(const QString& path, bool quiet = false, QString* error = nullptr);
    /// Answers the unsaved-changes prompt instead of a dialog (tests, scripted runs): returns
    /// Save, Discard or Cancel. Unset: a dialog (on the offscreen platform, where nobody can
    /// answer one, Discard with a warning).
    using PromptFn = std::function<QMessageBox::StandardButton()>;
    void setUnsavedChangesPrompt(PromptFn fn) { m_prompt = std::move(fn); }
    /// Asks whether to save unsaved changes before they are replaced; false: do not go on.
    bool maybeSave();
    /// Saves the session atomically. False with *error.
    bool saveSession(const QString& path, QString* error);
    QJsonObject sessionState() const;
    bool isModified() const { return m_modified; }
    void showWorkspace(const QString& name);
    /// Waits until every workspace's background work is done (for screenshots and tests).
    bool waitIdle(int timeoutMs);

protected:
    void closeEvent(class QCloseEvent* e) override;

private:
    void buildMenus();
    void openInputs();
    void openFolder();
    void openSessionDialog();
    bool save();
    bool saveAs();
    void exportAccepted();
    void setModified(bool m);
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void showError(const QString& what, const QString& detail);

    QTabWidget* m_tabs;
    FootprintWorkspace* m_footprint;
    SlrWorkspace* m_slr;
    CalibWorkspace* m_calib;
    RadiometryWorkspace* m_radiometry;
    QMenu* m_recentMenu = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QString m_sessionPath;
    bool m_modified = false;
    PromptFn m_prompt;
};

}  // namespace lwb::ui
