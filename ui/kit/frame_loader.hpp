#pragma once
// Where the footprint workspace's background work over many shots runs (loading frames,
// re-judging the list): a thread pool of every core but one, so the GUI thread keeps a core and
// the window stays responsive while hundreds of full frames load; and the rule for when a load
// shows its progress (any load that lasts longer than kProgressDelayMs).
class QThreadPool;

namespace lwb::ui {

/// Worker threads for loading and re-judging: max(1, ideal thread count − 1).
int loaderThreadCount();
/// The pool those workers run on (created on first use, lives as long as the process).
QThreadPool* loaderPool();
/// A load shows progress and Cancel once it has run this long.
constexpr int kProgressDelayMs = 300;

}  // namespace lwb::ui
