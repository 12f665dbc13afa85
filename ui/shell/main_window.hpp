#pragma once
// The workbench window: one tab per workspace, sessions (JSON, atomic saves, recent files,
// unsaved-changes prompt), settings, status bar, error dialogs.
#include <QJsonObject>
#include <QMainWindow>
#include <QSet>
#include <QMessageBox>
#include <functional>

#include "ui/kit/workspace.hpp"

class QTabWidget;
class QMenu;
class QAction;
class QActionGroup;
class QProgressBar;
class QPushButton;

class QTextBrowser;

namespace lwb::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    /// The workspaces in tab order (ui/shell/workspaces.cpp makes them).
    const QList<Workspace*>& workspaces() const { return m_workspaces; }
    /// The workspace of a key ("slr"), or null.
    Workspace* workspace(const QString& key) const;
    /// The workspace of a type (tests, benchmarks), or null.
    template <class W>
    W* workspace() const {
        for (Workspace* ws : m_workspaces)
            if (auto* w = qobject_cast<W*>(ws)) return w;
        return nullptr;
    }
    Workspace* currentWorkspace() const;
    QTabWidget* tabs() const { return m_tabs; }

    /// Loads the built-in demo in every workspace (after the unsaved-changes prompt; false when
    /// the analyst cancelled it).
    bool openDemo();
    /// Opens paths as inputs of one workspace (its own Open dialogs, a recent input): each must be
    /// one it takes (Workspace::claim). Asks about that workspace's unsaved work first, leaves the
    /// others' alone. False with *error naming what could not be opened and why, or when the
    /// analyst cancelled the unsaved-changes prompt (then nothing is opened, *error untouched).
    bool openInputsIn(Workspace* workspace, const QStringList& paths, QString* error = nullptr);
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
    bool maybeSave(Workspace* workspace = nullptr);
    /// Saves the session atomically. False with *error.
    bool saveSession(const QString& path, QString* error);
    QJsonObject sessionState() const;
    bool isModified() const { return !m_unsaved.isEmpty(); }
    /// Whether a workspace has unsaved work (its verdicts, notes, edits or parameters).
    bool hasUnsaved(Workspace* workspace) const { return m_unsaved.contains(workspace); }
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
    /// Which workspace and role a path opens in (the first workspace that claims it, the one in
    /// front asked first): "slr", "slr-cpf", "slr-sinex", "slr-npt", "footprint", "radiometry",
    /// "session" or "" (none).
    QString workspaceForPath(const QString& path) const;
    /// Ctrl+O / Ctrl+E: the current workspace's open and export.
    void openForCurrent();
    void exportForCurrent();
    /// The export entries of a workspace (its "Export…" buttons and menus), for Ctrl+E.
    QList<QAction*> exportActions(Workspace* workspace) { return workspace->exportActions(); }
    /// The open entries of a workspace, for Ctrl+O.
    QList<QAction*> openActions(Workspace* workspace) { return workspace->openActions(); }

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
    /// File ▸ Report…: the current workspace's PDF report, to a file the analyst names.
    void reportForCurrent();
    /// The report of the current workspace written to `path` (false: shown as an error).
    bool writeReportTo(const QString& path);
    void showUserGuide();
    void showShortcuts();

protected:
    void closeEvent(class QCloseEvent* e) override;
    void dragEnterEvent(class QDragEnterEvent* e) override;
    void dropEvent(class QDropEvent* e) override;

private:
    /// Inputs were opened in `workspace` from the window (files, folders, drops, the command line): see main_window.cpp.
    void inputsOpened(Workspace* workspace);
    /// A workspace's work changed (its modified signal), or was saved or replaced.
    void markUnsaved(Workspace* workspace);
    void markSaved(Workspace* workspace);
    /// The workspace and role that take a path ("" and null: none).
    Workspace* route(const InputProbe& probe, QString* role) const;
    /// Opens inputs routed to workspaces (by workspace, then role), in tab order: each asked about
    /// its unsaved work first when they replace its data. Problems appended; false when the
    /// analyst kept a workspace's unsaved work (nothing opened there).
    bool openRouted(const QMap<Workspace*, QMap<QString, QStringList>>& routed, int pass, QStringList* problems);
    void buildMenus();
    static void fitGuideImages(QTextBrowser* browser, int width);
    void rebuildRecentInputsMenu();
    void workspaceStatus(Workspace* workspace, const QString& message, int timeoutMs);
    void openSessionDialog();
    bool save();
    bool saveAs();
    void setModified(bool m);
    /// Every workspace's undo history cleared (new data everywhere: the demo, a session).
    void clearUndoHistories();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void showError(const QString& what, const QString& detail);

    QTabWidget* m_tabs;
    QList<Workspace*> m_workspaces;
    Workspace* m_loading = nullptr;  ///< the workspace whose load the progress bar shows
    QMenu* m_recentMenu = nullptr;
    QMenu* m_recentInputsMenu = nullptr;
    QActionGroup* m_workspaceGroup = nullptr;
    QAction *m_darkAction = nullptr, *m_lightAction = nullptr, *m_panelsAction = nullptr;
    bool m_dark = false;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QString m_sessionPath;
    QSet<Workspace*> m_unsaved;  ///< the workspaces with unsaved work
    PromptFn m_prompt;
};

}  // namespace lwb::ui
