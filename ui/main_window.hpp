#pragma once
// The workbench window: one tab per workspace, sessions (JSON, atomic saves, recent files,
// unsaved-changes prompt), settings, status bar, error dialogs.
#include <QJsonObject>
#include <QMainWindow>
#include <QSet>
#include <QMessageBox>
#include <functional>

class QTabWidget;
class QMenu;
class QAction;
class QActionGroup;
class QProgressBar;
class QPushButton;

class QTextBrowser;

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
    /// Largest session file opened (bytes); larger ones are refused with their size (a session is
    /// read whole and parsed twice: about 6 times its size in memory).
    static constexpr long long kMaxSessionBytes = 128LL << 20;
    /// Opens a session file (after the unsaved-changes prompt); on error shows a dialog (unless
    /// quiet) and keeps the current state.
    bool openSession(const QString& path, bool quiet = false, QString* error = nullptr);
    /// Answers the unsaved-changes prompt instead of a dialog (tests, scripted runs): returns
    /// Save, Discard or Cancel. Unset: a dialog (on the offscreen platform, where nobody can
    /// answer one, Discard with a warning).
    using PromptFn = std::function<QMessageBox::StandardButton()>;
    void setUnsavedChangesPrompt(PromptFn fn) { m_prompt = std::move(fn); }
    /// Asks whether to save unsaved changes before they are replaced: those of `workspace` (its
    /// data is about to be replaced), or of any workspace (nullptr: quitting, a new session, the
    /// demo). False: do not go on.
    bool maybeSave(QWidget* workspace = nullptr);
    /// Saves the session atomically. False with *error.
    bool saveSession(const QString& path, QString* error);
    QJsonObject sessionState() const;
    bool isModified() const { return !m_unsaved.isEmpty(); }
    /// Whether a workspace has unsaved work (its verdicts, notes, edits or parameters).
    bool hasUnsaved(QWidget* workspace) const { return m_unsaved.contains(workspace); }
    /// The session file the window's state was read from or saved to ("" when none, or when other
    /// inputs were opened since).
    QString sessionPath() const { return m_sessionPath; }
    void showWorkspace(const QString& name);
    /// Waits until every workspace's background work is done (for screenshots and tests).
    bool waitIdle(int timeoutMs);

    /// Opens files or folders where they belong (dropped on the window, recent inputs):
    /// CRD (.frd .fr2 .npt .np2 .crd) and O-C tables → SLR, and a CPF or SINEX file as its
    /// prediction or station coordinates (gzip-compressed ones too); a session (.json) → the session;
    /// images and folders → footprint (radiometry when it is the current workspace); a shot list
    /// (.csv) → footprint. False with *error naming what could not be opened and why.
    bool openPaths(const QStringList& paths, QString* error = nullptr);
    /// Which workspace a path opens in: "slr", "slr-cpf", "slr-sinex", "footprint", "radiometry",
    /// "session" or "" (none).
    QString workspaceForPath(const QString& path) const;
    /// Ctrl+O / Ctrl+E: the current workspace's open and export.
    void openForCurrent();
    void exportForCurrent();
    /// The export entries of a workspace (its "Export…" buttons and menus), for Ctrl+E.
    QList<QAction*> exportActions(QWidget* workspace);
    /// The open entries of a workspace, for Ctrl+O.
    QList<QAction*> openActions(QWidget* workspace);

    /// Light or dark (Fusion palette); saved in the settings; plots follow.
    void setDarkTheme(bool dark);
    bool isDarkTheme() const { return m_dark; }
    /// Shows or hides every workspace's parameter panel.
    void setPanelsVisible(bool visible);
    /// The recent inputs ("kind\tpath[\tpass]"), newest first.
    QStringList recentInputs() const;
    void addRecentInput(const QString& kind, const QString& path, int pass = -1);
    /// The keyboard shortcuts as "keys\twhat" lines (Help ▸ Keyboard shortcuts).
    QStringList shortcutList() const;
    void showUserGuide();
    void showShortcuts();

protected:
    void closeEvent(class QCloseEvent* e) override;
    void dragEnterEvent(class QDragEnterEvent* e) override;
    void dropEvent(class QDropEvent* e) override;

private:
    /// Inputs were opened in `workspace` from the window (files, folders, drops, the command line): see main_window.cpp.
    void inputsOpened(QWidget* workspace);
    /// A workspace's work changed (its modified signal), or was saved or replaced.
    void markUnsaved(QWidget* workspace);
    void markSaved(QWidget* workspace);
    void buildMenus();
    static void fitGuideImages(QTextBrowser* browser, int width);
    void rebuildRecentInputsMenu();
    void workspaceStatus(QWidget* workspace, const QString& message, int timeoutMs);
    void openInputs();
    void openFolder();
    void openSessionDialog();
    bool save();
    bool saveAs();
    void exportAccepted();
    void setModified(bool m);
    /// Every workspace's undo history cleared (new data everywhere: the demo, a session).
    void clearUndoHistories();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void showError(const QString& what, const QString& detail);

    QTabWidget* m_tabs;
    FootprintWorkspace* m_footprint;
    SlrWorkspace* m_slr;
    CalibWorkspace* m_calib;
    RadiometryWorkspace* m_radiometry;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_recentInputsMenu = nullptr;
    QActionGroup* m_workspaceGroup = nullptr;
    QAction *m_darkAction = nullptr, *m_lightAction = nullptr, *m_panelsAction = nullptr;
    bool m_dark = false;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QString m_sessionPath;
    QSet<QWidget*> m_unsaved;  ///< the workspaces with unsaved work
    PromptFn m_prompt;
};

}  // namespace lwb::ui
