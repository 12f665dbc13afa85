#pragma once
// A workspace of the workbench as a document (Tiled's Editor/Document; ../shared/docs/
// ARCHITECTURE.md point 16): it opens its own inputs, saves and restores its state as JSON, has
// its own undo stack (undoStackOf(this)) and unsaved state, its docks and its actions. The main
// window (ui/shell/) holds a list of them, made by makeWorkspaces() (ui/shell/workspaces.cpp,
// the one place that names them), and names none: adding a workspace is one folder under ui/
// and one line there.
#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <string>
#include <vector>

#include "core/common/json.hpp"

class QAction;

namespace lwb::ui {

/// What the window knows of a path offered to it (dropped, given on the command line, from a
/// recent-inputs entry) when it asks the workspaces which of them takes it.
struct InputProbe {
    QString path;
    bool isDir = false;
    QString suffix;    ///< lower case, without a trailing ".gz" (core::inputExtension)
    bool gz = false;   ///< the name ends in .gz
    QString head;      ///< the first line that is not blank or a '#' comment, lower case (decompressed)
};

/// What opening a workspace's inputs did.
struct OpenOutcome {
    bool opened = false;     ///< something was opened (the workspace comes to the front)
    bool replaced = false;   ///< its data was replaced (its unsaved work is gone: it was offered for saving before)
    QStringList problems;    ///< one line per input that could not be opened, with the path and why
    QString recentPath;      ///< what Recent inputs remembers ("" none)
    int recentPass = -1;     ///< and which pass of it
};

class Workspace : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    /// Its key in sessions, recent inputs, --workspace and showWorkspace ("footprint").
    virtual QString key() const = 0;
    /// Its tab and menu title.
    virtual QString title() const = 0;

    /// Session state (a JSON object under key() in the session file).
    virtual QJsonObject saveState() const = 0;
    /// How far readState goes: its checks only (keys, parameters, names, view settings), then
    /// also reading the inputs (a pass, an image, tables: kept for the restore), then applying.
    enum class StatePhase { Check, Prepare, Apply };

    /// Restores a session's state; `doc` is the parsed session (for file:line:col in messages),
    /// `at` this state's path in it (empty: {key()}). False with *error, and the state as it was.
    /// After a prepareState of the same state it uses the inputs that read, and cannot fail on
    /// them; what it does not use is dropped.
    bool restoreState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc = nullptr,
                      const std::vector<std::string>& at = {}) {
        const bool ok = readState(state, error, doc, at.empty() ? std::vector<std::string>{key().toStdString()} : at, StatePhase::Apply);
        dropPrepared();
        return ok;
    }
    /// restoreState's checks that read no file (keys, parameters, names, view settings), with
    /// nothing changed: the window makes them for every workspace's part of a session first.
    bool checkState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc = nullptr,
                    const std::vector<std::string>& at = {}) {
        return readState(state, error, doc, at.empty() ? std::vector<std::string>{key().toStdString()} : at, StatePhase::Check);
    }
    /// checkState and the inputs read (a pass, an image, tables) as restoreState would read them,
    /// with nothing shown changed; what was read is kept for the restoreState of this state that
    /// follows. The window prepares every part after checking every part and before restoring
    /// any: a session refused for one part, even for an input that cannot be read, starts no
    /// work in another and leaves every workspace as it was.
    bool prepareState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc = nullptr,
                      const std::vector<std::string>& at = {}) {
        dropPrepared();
        const bool ok = readState(state, error, doc, at.empty() ? std::vector<std::string>{key().toStdString()} : at, StatePhase::Prepare);
        if (!ok) dropPrepared();
        return ok;
    }
    /// Frees the inputs the last prepareState read (the window's session was refused for another part).
    virtual void dropPrepared() {}
    /// Loads the built-in demo.
    virtual void openDemo() = 0;
    /// What the demo holds, for the status line ("240 simulated footprint shots").
    virtual QString demoSummary() const = 0;
    /// True when its background work is done within timeoutMs.
    virtual bool waitIdle(int timeoutMs) = 0;
    /// Shows one of its tabs ("trend" of "footprint:trend").
    virtual void showTab(const QString& name) { Q_UNUSED(name); }

    /// The role this workspace would open `probe` in ("" none): key() for its main data, another
    /// name ("slr-cpf") for an input that goes with it. `current`: it is the workspace in front
    /// (asked first), or the input was given to it by name (its own Open dialogs).
    virtual QString claim(const InputProbe& probe, bool current) const = 0;
    /// Whether opening inputs of `role` replaces its data (asked about its unsaved work before).
    virtual bool replacesData(const QString& role) const { return role == key(); }
    /// Opens the inputs it claimed, by role (`pass`: which pass of a ranging file, -1 the first
    /// or the only one).
    virtual OpenOutcome openInputs(const QMap<QString, QStringList>& byRole, int pass) = 0;

    /// Ctrl+O / Ctrl+E: its open and export entries (made for the call are parented to the
    /// workspace and deleted after it). Default: its "…" buttons, its "Export" buttons and menus.
    virtual QList<QAction*> openActions();
    virtual QList<QAction*> exportActions();
    /// Entries it adds to the File menu, after the window's own open and export entries.
    virtual QList<QAction*> fileOpenActions() { return {}; }
    virtual QList<QAction*> fileExportActions() { return {}; }
    /// The keys it handles itself, as "keys\twhat" lines (Help ▸ Keyboard shortcuts).
    virtual QStringList shortcutNotes() const { return {}; }
    /// Stops a long load it reported with progress().
    virtual void cancelWork() {}
    /// The laserwb-cli command that reproduces its current result (Edit ▸ Copy as command line),
    /// "" when there is none; *note says what the command cannot carry (manual edits).
    virtual QString commandLine(QString* note) const {
        Q_UNUSED(note);
        return QString();
    }
    /// The same as a Python script of the laserwb module (Edit ▸ Copy as Python), "" when none.
    virtual QString pythonScript(QString* note) const {
        Q_UNUSED(note);
        return QString();
    }
    /// File ▸ Report…: the suggested file name of its current result's PDF report, "" when it
    /// has nothing to report; writeReport writes it (false with *error).
    virtual QString reportName() const { return QString(); }
    virtual bool writeReport(const QString& path, QString* error) const {
        Q_UNUSED(path);
        if (error) *error = QString();
        return false;
    }

signals:
    /// Something a session would save changed (a verdict, a note, an edit, a parameter).
    void modified();
    /// A line for the status bar (shown while the workspace is in front).
    void status(const QString& message);
    /// Its own Open dialogs chose inputs: the window opens them here (asking about unsaved work).
    void openRequested(const QStringList& paths);
    /// An error to show the analyst (a dialog; a warning on the offscreen platform).
    void failed(const QString& what, const QString& detail);
    /// Progress of a long load (done == total: finished), its label format ("%v / %m shots").
    void progress(int done, int total, const QString& format);

protected:
    /// checkState's, prepareState's and restoreState's work, as far as `phase`: nothing shown
    /// changes before StatePhase::Apply (the inputs Prepare reads are kept; dropPrepared frees them).
    virtual bool readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                           const std::vector<std::string>& at, StatePhase phase) = 0;
};

}  // namespace lwb::ui
