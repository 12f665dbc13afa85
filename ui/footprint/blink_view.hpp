#pragma once
// Blink and tile several shots, as DS9's frames: Tile shows them in a grid, Blink shows one at
// a time and cycles them at a chosen interval. Zoom and pan are locked (a change on one tile
// moves every tile, relative to each one's fit), and so is the display: one set of limits and
// stretch for every tile — the limits of the shot in front in the automatic modes, the typed or
// dragged ones in Manual — so that a brightness change between shots shows as one.
#include <QString>
#include <QWidget>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/display_stretch.hpp"
#include "ui/kit/color_maps.hpp"
#include "ui/kit/display_controls.hpp"
#include "ui/kit/image_view.hpp"

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;
class QGridLayout;

namespace lwb::ui {

/// One shot to blink: its ROI (CV_32FC1), the full-image position of its pixel (0, 0) and the
/// fitted centre (ROI coordinates) when there is one.
struct BlinkFrame {
    QString name;
    cv::Mat data;
    QPointF origin;
    bool hasCentre = false;
    QPointF centre;
};

class BlinkView : public QWidget {
    Q_OBJECT
public:
    enum class Mode { Tile, Blink };
    BlinkView(std::vector<BlinkFrame> frames, ColorMap map, const DisplaySettings& display, QWidget* parent = nullptr);

    int frameCount() const { return int(m_frames.size()); }
    ImageView* tile(int i) const { return m_tiles.value(i); }
    void setMode(Mode m);
    Mode mode() const { return m_mode; }
    /// The frame in front (in Blink the one shown; its limits are every tile's in the automatic modes).
    int currentFrame() const { return m_current; }
    void setCurrentFrame(int i);
    void step(int delta);
    void setInterval(int ms);
    int interval() const;
    void setPlaying(bool on);
    bool playing() const;
    DisplayControls* displayControls() const { return m_display; }
    ColorBar* colorBar() const { return m_bar; }
    /// The limits every tile is drawn with.
    core::DisplayLimits limits() const { return m_limits; }
    /// The limits tile i was last drawn with (tests: all the same).
    core::DisplayLimits tileLimits(int i) const { return m_tileLimits.value(i); }

protected:
    bool eventFilter(QObject* o, QEvent* e) override;

private:
    QWidget* buildControls();
    void render();
    void syncViews(int from);
    void applyMode();

    std::vector<BlinkFrame> m_frames;
    ColorMap m_map;
    Mode m_mode = Mode::Tile;
    int m_current = 0;
    QList<ImageView*> m_tiles;
    QList<QWidget*> m_cells;
    QList<core::DisplayLimits> m_tileLimits;
    core::DisplayLimits m_limits;
    ImageView::ViewState m_state;
    bool m_syncing = false;
    DisplayControls* m_display = nullptr;
    ColorBar* m_bar = nullptr;
    QComboBox* m_modeBox = nullptr;
    QSpinBox* m_interval = nullptr;
    QPushButton* m_play = nullptr;
    QLabel* m_frameLabel = nullptr;
    QGridLayout* m_grid = nullptr;
    QTimer* m_timer = nullptr;
};

}  // namespace lwb::ui
