#include "core/slr/pass_report.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <memory>

#include "core/common/sha256.hpp"
#include "core/common/text.hpp"
#include "core/slr/slr_run.hpp"
#include "core/slr/slr_time.hpp"
#include "lwb_version.hpp"

namespace lwb::core::slr {
namespace {

// A4 in points; every length below is in points (1/72 in).
constexpr double kPageW = 595.276, kPageH = 841.89, kMargin = 36;
constexpr int kRasterScale = 4;  // raster pixels per point of a plot (288 dpi)

struct Rgb {
    double r, g, b;
};
constexpr Rgb kInk{0.10, 0.10, 0.12}, kGrey{0.45, 0.45, 0.48}, kLight{0.82, 0.82, 0.84};
constexpr Rgb kSignal{0.12, 0.40, 0.75}, kRecovered{0.10, 0.60, 0.55}, kNoise{0.62, 0.62, 0.65};
constexpr Rgb kRejected{0.90, 0.45, 0.05}, kNormal{0.80, 0.10, 0.15}, kOk{0.10, 0.50, 0.20};

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// Values of a nice step (1, 2 or 5 × 10^k) inside [lo, hi], about `want` of them.
std::vector<double> niceTicks(double lo, double hi, int want) {
    std::vector<double> out;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return out;
    const double raw = (hi - lo) / std::max(1, want);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
    return out;
}

// Seconds of day as the report writes them: "hh:mm" or "hh:mm:ss".
std::string clock(double sod, bool seconds) {
    double s = std::fmod(sod, 86400.0);
    if (s < 0) s += 86400;
    const long t = std::lround(s);
    char b[32];
    if (seconds) std::snprintf(b, sizeof b, "%02ld:%02ld:%02ld", (t / 3600) % 24, (t / 60) % 60, t % 60);
    else std::snprintf(b, sizeof b, "%02ld:%02ld", (t / 3600) % 24, (t / 60) % 60);
    return b;
}

class Page {
public:
    explicit Page(cairo_t* cr) : m_cr(cr) {}
    cairo_t* cr() const { return m_cr; }
    void color(const Rgb& c) { cairo_set_source_rgb(m_cr, c.r, c.g, c.b); }
    void font(double size, bool bold = false, bool mono = false) {
        cairo_select_font_face(m_cr, mono ? "monospace" : "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(m_cr, size);
    }
    double width(const std::string& s) {
        cairo_text_extents_t e;
        cairo_text_extents(m_cr, s.c_str(), &e);
        return e.x_advance;
    }
    // Text with its baseline at y; align 0 left, 0.5 centre, 1 right of x.
    void text(double x, double y, const std::string& s, double align = 0) {
        cairo_move_to(m_cr, x - align * width(s), y);
        cairo_show_text(m_cr, s.c_str());
    }
    // Text cut to `maxWidth` with an ellipsis.
    void textFit(double x, double y, std::string s, double maxWidth) {
        if (width(s) > maxWidth) {
            while (!s.empty() && width(s + "…") > maxWidth) {
                s.pop_back();
                while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0) == 0x80) s.pop_back();
            }
            s += "…";
        }
        text(x, y, s);
    }
    // Words wrapped into lines of `maxWidth`, from baseline y; returns the baseline after the last line.
    double paragraph(double x, double y, const std::string& s, double maxWidth, double lineHeight, int maxLines = 100) {
        std::string line;
        int lines = 0;
        size_t i = 0;
        while (i < s.size() && lines < maxLines) {
            size_t j = s.find(' ', i);
            if (j == std::string::npos) j = s.size();
            const std::string word = s.substr(i, j - i);
            const std::string tryLine = line.empty() ? word : line + " " + word;
            if (!line.empty() && width(tryLine) > maxWidth) {
                textFit(x, y, line, maxWidth);
                y += lineHeight;
                ++lines;
                line = word;
            } else {
                line = tryLine;
            }
            i = j + 1;
        }
        if (!line.empty() && lines < maxLines) {
            textFit(x, y, line, maxWidth);
            y += lineHeight;
        }
        return y;
    }
    void rule(double x0, double y0, double x1, double y1, const Rgb& c, double w = 0.5) {
        color(c);
        cairo_set_line_width(m_cr, w);
        cairo_move_to(m_cr, x0, y0);
        cairo_line_to(m_cr, x1, y1);
        cairo_stroke(m_cr);
    }

private:
    cairo_t* m_cr;
};

// A plot box: data ranges mapped into a rectangle, its frame, ticks and titles.
struct Plot {
    double x, y, w, h;          // the data area on the page
    double x0, x1, y0, y1;      // data ranges
    double px(double v) const { return x + (v - x0) / (x1 - x0) * w; }
    double py(double v) const { return y + h - (v - y0) / (y1 - y0) * h; }
};

void drawFrame(Page& pg, const Plot& p, const std::string& title, const std::string& xTitle, const std::string& yTitle,
               const std::function<std::string(double)>& xLabel, const std::function<std::string(double)>& yLabel) {
    cairo_t* cr = pg.cr();
    pg.font(6.5);
    const bool grid = !yLabel(p.y0).empty() || !yLabel(p.y1).empty();
    for (double v : grid ? niceTicks(p.y0, p.y1, 5) : std::vector<double>{}) {
        const double yy = p.py(v);
        pg.rule(p.x, yy, p.x + p.w, yy, kLight, 0.3);
        pg.color(kInk);
        pg.text(p.x - 3, yy + 2.2, yLabel(v), 1);
    }
    for (double v : xLabel(p.x0).empty() && xLabel(p.x1).empty() ? std::vector<double>{} : niceTicks(p.x0, p.x1, 5)) {
        const double xx = p.px(v);
        pg.rule(xx, p.y + p.h, xx, p.y + p.h + 2.5, kInk, 0.5);
        pg.color(kInk);
        pg.text(xx, p.y + p.h + 10, xLabel(v), 0.5);
    }
    pg.color(kInk);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, p.x, p.y, p.w, p.h);
    cairo_stroke(cr);
    pg.font(8, true);
    pg.text(p.x, p.y - 5, title);
    pg.font(6.5);
    pg.color(kGrey);
    pg.text(p.x + p.w / 2, p.y + p.h + 19, xTitle, 0.5);
    cairo_save(cr);
    cairo_move_to(cr, p.x - 30, p.y + p.h / 2 + pg.width(yTitle) / 2);
    cairo_rotate(cr, -M_PI / 2);
    cairo_show_text(cr, yTitle.c_str());
    cairo_restore(cr);
}

// A raster over a plot's data area, kRasterScale pixels a point, transparent where nothing is drawn.
class Raster {
public:
    explicit Raster(const Plot& p)
        : m_plot(p), m_w(std::max(1, int(p.w * kRasterScale))), m_h(std::max(1, int(p.h * kRasterScale))),
          m_surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, m_w, m_h)) {
        cairo_surface_flush(m_surface);
        m_data = cairo_image_surface_get_data(m_surface);
        m_stride = cairo_image_surface_get_stride(m_surface);
        if (m_data) std::fill(m_data, m_data + size_t(m_stride) * m_h, 0);
    }
    ~Raster() { cairo_surface_destroy(m_surface); }
    Raster(const Raster&) = delete;
    Raster& operator=(const Raster&) = delete;
    // A dot of `radius` raster pixels at data (vx, vy); outside the ranges: nothing.
    void dot(double vx, double vy, const Rgb& c, int radius = 2) {
        if (!m_data || !std::isfinite(vx) || !std::isfinite(vy)) return;
        const double fx = (vx - m_plot.x0) / (m_plot.x1 - m_plot.x0) * m_w;
        const double fy = m_h - (vy - m_plot.y0) / (m_plot.y1 - m_plot.y0) * m_h;
        if (!(fx >= 0 && fx < m_w && fy >= 0 && fy < m_h)) return;
        fill(int(fx) - radius / 2, int(fy) - radius / 2, radius, radius, c);
    }
    // A filled cell in raster pixels.
    void fill(int x, int y, int w, int h, const Rgb& c) {
        const uint32_t argb = 0xFF000000u | (uint32_t(std::lround(c.r * 255)) << 16) | (uint32_t(std::lround(c.g * 255)) << 8) |
                              uint32_t(std::lround(c.b * 255));
        for (int yy = std::max(0, y); yy < std::min(m_h, y + h); ++yy) {
            auto* row = reinterpret_cast<uint32_t*>(m_data + size_t(yy) * m_stride);
            for (int xx = std::max(0, x); xx < std::min(m_w, x + w); ++xx) row[xx] = argb;
        }
    }
    int width() const { return m_w; }
    int height() const { return m_h; }
    void paint(cairo_t* cr, bool smooth = true) {
        cairo_surface_mark_dirty(m_surface);
        cairo_save(cr);
        cairo_rectangle(cr, m_plot.x, m_plot.y, m_plot.w, m_plot.h);
        cairo_clip(cr);
        cairo_translate(cr, m_plot.x, m_plot.y);
        cairo_scale(cr, m_plot.w / m_w, m_plot.h / m_h);
        cairo_set_source_surface(cr, m_surface, 0, 0);
        cairo_pattern_set_filter(cairo_get_source(cr), smooth ? CAIRO_FILTER_GOOD : CAIRO_FILTER_NEAREST);
        cairo_paint(cr);
        cairo_restore(cr);
    }

private:
    Plot m_plot;
    int m_w, m_h;
    cairo_surface_t* m_surface;
    unsigned char* m_data = nullptr;
    int m_stride = 0;
};

// A line of 6 pt text at the top left inside a plot, on a white ground over the data.
void caption(Page& pg, const Plot& p, const std::string& text) {
    pg.font(6);
    cairo_set_source_rgba(pg.cr(), 1, 1, 1, 0.85);
    cairo_rectangle(pg.cr(), p.x + 2, p.y + 2, std::min(pg.width(text) + 4, p.w - 4), 8.5);
    cairo_fill(pg.cr());
    pg.color(kInk);
    pg.textFit(p.x + 4, p.y + 8.5, text, p.w - 8);
}

void noData(Page& pg, const Plot& p, const std::string& why) {
    pg.font(7);
    pg.color(kGrey);
    pg.paragraph(p.x + 8, p.y + p.h / 2, why, p.w - 16, 9, 3);
}

// Range of finite values with a margin; [v−1, v+1] for one value.
std::pair<double, double> span(const std::vector<double>& v, double margin = 0.04) {
    double lo = INFINITY, hi = -INFINITY;
    for (double x : v)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!(hi >= lo)) return {0, 1};
    if (hi == lo) return {lo - 1, hi + 1};
    const double m = (hi - lo) * margin;
    return {lo - m, hi + m};
}

struct Context {
    const PassData& pass;
    const PassRunResult& run;
    const PassReport& report;
    const NpComparison* station;  // the station's normal points compared (null: none given)
    bool timeOfDay;          // CRD epochs: seconds of the pass day, labelled UTC
    double ocUnit;           // s per unit of the O-C axis
    std::string ocUnitName;
};

std::function<std::string(double)> timeLabels(const Context& c, double spanS) {
    if (!c.timeOfDay) return [](double v) { return fmt("%g", v); };
    const bool seconds = spanS < 600;
    return [seconds](double v) { return clock(v, seconds); };
}

void drawOc(Page& pg, const Context& c, const Plot& area) {
    const PassData& pass = c.pass;
    const PassRunResult& r = c.run;
    Plot p = area;
    std::tie(p.x0, p.x1) = span(pass.t, 0.02);
    std::vector<double> oc(pass.oc.size());
    for (size_t i = 0; i < oc.size(); ++i) oc[i] = pass.oc[i] / c.ocUnit;
    std::tie(p.y0, p.y1) = span(oc);
    drawFrame(pg, p, "O-C and screening", c.timeOfDay ? "UTC" : "epoch (s)", "O-C (" + c.ocUnitName + ", two-way)",
              timeLabels(c, p.x1 - p.x0), [](double v) { return fmt("%g", v); });
    Raster ras(p);
    const bool post = r.postOk && r.post.kept.size() == oc.size();
    for (int pass2 = 0; pass2 < 2; ++pass2)  // noise under the track
        for (size_t i = 0; i < oc.size(); ++i) {
            const bool acc = i < r.accepted.size() && r.accepted[i];
            if (acc != (pass2 == 1)) continue;
            Rgb col = kNoise;
            const PointClass pc = i < r.classes.size() ? r.classes[i] : PointClass::Signal;
            if (acc) col = post && !r.post.kept[i] ? kRejected : (pc == PointClass::Recovered || pc == PointClass::Band ? kRecovered : kSignal);
            ras.dot(pass.t[i], oc[i], col, acc ? 3 : 2);
        }
    ras.paint(pg.cr());
    // Legend, on a white ground over the points.
    pg.font(6);
    const std::vector<std::pair<std::string, Rgb>> legend{
        {"signal", kSignal}, {"recovered, band", kRecovered}, {"post-fit rejected", kRejected}, {"noise", kNoise}};
    double legendW = 4;
    for (const auto& item : legend) legendW += pg.width(item.first) + 15;
    cairo_set_source_rgba(pg.cr(), 1, 1, 1, 0.85);
    cairo_rectangle(pg.cr(), p.x + 2, p.y + 2, std::min(p.w - 4, legendW - 8), 8.5);
    cairo_fill(pg.cr());
    double lx = p.x + 4;
    for (const auto& [name, col] : legend) {
        pg.color(col);
        cairo_rectangle(pg.cr(), lx, p.y + 4.5, 4, 4);
        cairo_fill(pg.cr());
        pg.color(kInk);
        pg.text(lx + 6.5, p.y + 8.5, name);
        lx += pg.width(name) + 15;
    }
}

void drawResiduals(Page& pg, const Context& c, const Plot& area) {
    const PassRunResult& r = c.run;
    Plot p = area;
    std::tie(p.x0, p.x1) = span(c.pass.t, 0.02);
    if (!r.postOk || r.post.residuals.size() != c.pass.t.size()) {
        p.y0 = -1, p.y1 = 1;
        drawFrame(pg, p, "Post-fit residuals", c.timeOfDay ? "UTC" : "epoch (s)", "residual (ps)", timeLabels(c, p.x1 - p.x0),
                  [](double) { return std::string(); });
        noData(pg, p, "No post-fit: " + (r.postNote.empty() ? std::string("fewer than two accepted points") : r.postNote));
        return;
    }
    const double sigmaPs = std::isfinite(r.post.sigmaS) && r.post.sigmaS > 0 ? r.post.sigmaS * 1e12 : 100;
    const double lim = std::max(6 * sigmaPs, 1.0);
    p.y0 = -lim, p.y1 = lim;
    drawFrame(pg, p, "Post-fit residuals and normal points", c.timeOfDay ? "UTC" : "epoch (s)", "residual (ps)",
              timeLabels(c, p.x1 - p.x0), [](double v) { return fmt("%g", v); });
    Raster ras(p);
    for (size_t i = 0; i < r.post.residuals.size(); ++i) {
        if (i >= r.accepted.size() || !r.accepted[i]) continue;
        const double v = std::clamp(r.post.residuals[i] * 1e12, -lim * 0.999, lim * 0.999);
        ras.dot(c.pass.t[i], v, r.post.kept[i] ? kSignal : kRejected, 3);
    }
    ras.paint(pg.cr());
    // The normal-point bins: their limits, and each point's mean residual.
    cairo_t* cr = pg.cr();
    for (const NormalPoint& np : r.post.normalPoints) {
        const double xx = p.px(np.binStartS);
        if (xx > p.x && xx < p.x + p.w) pg.rule(xx, p.y, xx, p.y + p.h, kLight, 0.3);
        const double cx = p.px(np.epochS), cy = p.py(np.meanResidualS * 1e12);
        pg.color(kNormal);
        cairo_move_to(cr, cx, cy - 3);
        cairo_line_to(cr, cx + 3, cy);
        cairo_line_to(cr, cx, cy + 3);
        cairo_line_to(cr, cx - 3, cy);
        cairo_close_path(cr);
        cairo_fill(cr);
    }
    caption(pg, p, "kept, rejected (orange), normal points (red) with their bins; σ = " + fmt("%.0f", sigmaPs) + " ps");
}

void drawBinaryImage(Page& pg, const Context& c, const Plot& area) {
    const PassData& pass = c.pass;
    const ScreenResult& s = c.run.screen;
    Plot p = area;
    p.x0 = 0, p.x1 = 1, p.y0 = 0, p.y1 = 1;
    const std::vector<double>& flat = s.flattenS;
    std::vector<int64_t> rows(pass.t.size()), cols(pass.t.size());
    int64_t rMin = INT64_MAX, rMax = INT64_MIN, cMin = INT64_MAX, cMax = INT64_MIN;
    size_t mapped = 0;
    for (size_t i = 0; i < pass.t.size(); ++i) {
        const double oc = pass.oc[i] - (flat.size() == pass.oc.size() ? flat[i] : 0.0);
        if (!mapPoint(pass.t[i], oc, s.magT, s.magOc, &rows[i], &cols[i])) {
            rows[i] = INT64_MIN;
            continue;
        }
        rMin = std::min(rMin, rows[i]), rMax = std::max(rMax, rows[i]);
        cMin = std::min(cMin, cols[i]), cMax = std::max(cMax, cols[i]);
        ++mapped;
    }
    const std::string title = "Binary image (mag_T " + fmt("%.3g", s.magT) + ", mag_OC " + fmt("%.3g", s.magOc) + " px/s)";
    if (mapped == 0 || !(s.magT > 0)) {
        drawFrame(pg, p, title, "time", "O-C", [](double) { return std::string(); }, [](double) { return std::string(); });
        noData(pg, p, "No image: the screening mapped no point.");
        return;
    }
    // Image pixels per raster cell: the image whole in the box (time across, O-C up).
    Raster ras(p);
    const double extentT = double(rMax - rMin + 1), extentOc = double(cMax - cMin + 1);
    const double perX = std::max(1.0, extentT / ras.width()), perY = std::max(1.0, extentOc / ras.height());
    const int cellW = std::max(1, int(ras.width() / std::ceil(extentT / perX)));
    const int cellH = std::max(1, int(ras.height() / std::ceil(extentOc / perY)));
    for (int round = 0; round < 2; ++round)
        for (size_t i = 0; i < rows.size(); ++i) {
            if (rows[i] == INT64_MIN) continue;
            const bool acc = i < c.run.accepted.size() && c.run.accepted[i];
            if (acc != (round == 1)) continue;
            const int cx = int(double(rows[i] - rMin) / perX), cy = int(double(cols[i] - cMin) / perY);
            ras.fill(cx * cellW, ras.height() - (cy + 1) * cellH, cellW, cellH, acc ? kSignal : kInk);
        }
    ras.paint(pg.cr(), false);
    drawFrame(pg, p, title, fmt("%.0f", extentT) + " × " + fmt("%.0f", extentOc) + " px, " + std::to_string(s.regionCount) +
                                " regions (" + std::to_string(s.linearRegions) + " linear)",
              "", [](double) { return std::string(); }, [](double) { return std::string(); });
    caption(pg, p, "occupied pixels; the accepted regions in blue");
}

void drawHistogram(Page& pg, const Context& c, const Plot& area) {
    const PassRunResult& r = c.run;
    Plot p = area;
    if (!r.postOk || r.post.stats.n < 2) {
        p.x0 = -1, p.x1 = 1, p.y0 = 0, p.y1 = 1;
        drawFrame(pg, p, "Residual histogram", "residual (ps)", "points", [](double) { return std::string(); },
                  [](double) { return std::string(); });
        noData(pg, p, "No kept residuals.");
        return;
    }
    const double sigmaPs = r.post.sigmaS > 0 ? r.post.sigmaS * 1e12 : r.post.stats.rms * 1e12;
    const double lim = 4 * std::max(sigmaPs, 1e-3);
    constexpr int kBins = 40;
    std::vector<long long> counts(kBins, 0);
    for (size_t i = 0; i < r.post.residuals.size(); ++i) {
        if (i >= r.post.kept.size() || !r.post.kept[i]) continue;
        const double v = r.post.residuals[i] * 1e12;
        const int b = int(std::floor((v + lim) / (2 * lim) * kBins));
        if (b >= 0 && b < kBins) ++counts[size_t(b)];
    }
    const long long top = *std::max_element(counts.begin(), counts.end());
    p.x0 = -lim, p.x1 = lim, p.y0 = 0, p.y1 = std::max<long long>(1, top) * 1.1;
    cairo_t* cr = pg.cr();
    pg.color(kSignal);
    for (int b = 0; b < kBins; ++b) {
        const double a = -lim + 2 * lim * b / kBins, z = a + 2 * lim / kBins;
        cairo_rectangle(cr, p.px(a), p.py(double(counts[size_t(b)])), p.px(z) - p.px(a), p.py(0) - p.py(double(counts[size_t(b)])));
    }
    cairo_fill(cr);
    // The normal curve of the same σ and count.
    const double n = double(r.post.stats.n), width = 2 * lim / kBins;
    pg.color(kNormal);
    cairo_set_line_width(cr, 0.7);
    for (int k = 0; k <= 200; ++k) {
        const double v = -lim + 2 * lim * k / 200;
        const double y = n * width / (sigmaPs * std::sqrt(2 * M_PI)) * std::exp(-0.5 * v * v / (sigmaPs * sigmaPs));
        if (k == 0) cairo_move_to(cr, p.px(v), p.py(std::min(y, p.y1)));
        else cairo_line_to(cr, p.px(v), p.py(std::min(y, p.y1)));
    }
    cairo_stroke(cr);
    drawFrame(pg, p, "Residual histogram (kept points)", "residual (ps)", "points", [](double v) { return fmt("%g", v); },
              [](double v) { return fmt("%g", v); });
    caption(pg, p,
            "RMS " + fmt("%.1f", r.post.stats.rms * 1e12) + " ps, skew " + fmt("%.2f", r.post.stats.skew) + ", kurtosis " +
                fmt("%.2f", r.post.stats.kurtosis) + "; normal curve of σ in red");
}

// Label: value rows in two columns from (x, y); returns the baseline after the last.
double keyValues(Page& pg, double x, double y, double w, const std::vector<std::pair<std::string, std::string>>& rows) {
    for (const auto& [k, v] : rows) {
        pg.font(6.5);
        pg.color(kGrey);
        pg.text(x, y, k);
        pg.color(kInk);
        pg.textFit(x + 92, y, v, w - 92);
        y += 8.6;
    }
    return y;
}

std::string autoMark(bool a) { return a ? " (auto)" : ""; }

double drawParameters(Page& pg, const Context& c, double x, double y, double w) {
    const ScreenResult& s = c.run.screen;
    const PassSettings& st = *c.report.settings;
    const SlrParams& prm = st.params;
    pg.font(8, true);
    pg.color(kInk);
    pg.text(x, y, "Parameters");
    y += 11;
    std::vector<std::pair<std::string, std::string>> rows = {
        {"mag_T", fmt("%g", s.magT) + " px/s" + autoMark(s.autoMagT)},
        {"mag_OC", fmt("%g", s.magOc) + " px/s" + autoMark(s.autoMagOc)},
        {"area limit", std::to_string(s.areaLimit) + " px" + autoMark(s.autoArea)},
        {"connectivity", std::to_string(s.connectivity) + autoMark(s.autoConnectivity)},
        {"refinement rounds", std::to_string(s.refinedRounds)},
    };
    if (c.run.postOk) {
        const PostfitResult& p = c.run.post;
        rows.push_back({"post-fit", "degree " + std::to_string(p.degree) + ", " + std::to_string(p.iterations) + " iterations, " +
                                        std::to_string(p.rejected) + " of " + std::to_string(p.used) + " rejected"});
        rows.push_back({"normal-point bin", fmt("%g", p.binLengthS) + " s, at least " + std::to_string(p.minPointsPerBin) + " ranges"});
    }
    rows.push_back({"preset", st.presetName.empty() ? std::string("none") : st.presetName});
    y = keyValues(pg, x, y, w, rows);
    // Every field that differs from the schema's defaults, as --set reads it.
    const Schema<SlrParams>& schema = slrSchema();
    std::string changed;
    for (const std::string& key : schema.changedKeys(SlrParams{}, prm))
        if (const auto* f = schema.find(key)) changed += (changed.empty() ? "" : ", ") + key + "=" + schema.valueText(*f, prm);
    pg.font(6.5);
    pg.color(kGrey);
    pg.text(x, y, "changed from defaults");
    pg.color(kInk);
    y = pg.paragraph(x + 92, y, changed.empty() ? "none" : changed, w - 92, 8.2, 6);
    for (const std::string& n : st.notes) {
        pg.color(kGrey);
        y = pg.paragraph(x, y, n, w, 8.2, 2);
    }
    return y;
}

double drawNormalPoints(Page& pg, const Context& c, double x, double y, double w, double bottom) {
    const DeliveredNormalPoints d = deliveredNormalPoints(c.run);
    pg.font(8, true);
    pg.color(kInk);
    pg.text(x, y, "Normal points (" + std::to_string(d.points.size()) + ")");
    y += 11;
    if (d.points.empty()) {
        pg.font(6.5);
        pg.color(kGrey);
        return pg.paragraph(x, y, "None: " + d.noneReason, w, 8.2, 4);
    }
    const bool station = c.station && c.station->ok;
    const std::vector<std::pair<std::string, double>> cols = {{"#", 0},          {"UTC", 14},       {"ranges", 62},
                                                              {"RMS (ps)", 96},  {"residual (ps)", 136},
                                                              {"return (%)", 188}, {station ? "Δ station (mm)" : "", 228}};
    pg.font(6.2, true);
    for (const auto& [name, at] : cols) pg.text(x + at, y, name);
    pg.rule(x, y + 2, x + w, y + 2, kLight, 0.4);
    y += 9;
    pg.font(6.2, false, true);
    const double rowH = 7.8;
    const size_t fit = size_t(std::max(1.0, std::floor((bottom - y) / rowH)));
    for (size_t i = 0; i < d.points.size(); ++i) {
        if (i + 1 == fit && d.points.size() > fit) {
            pg.font(6.2);
            pg.color(kGrey);
            pg.text(x, y, "… and " + std::to_string(d.points.size() - i) + " more: the normal-point file lists them all");
            y += rowH;
            break;
        }
        const NormalPoint& np = d.points[i];
        pg.color(kInk);
        pg.text(x, y, std::to_string(i + 1));
        pg.text(x + 14, y, c.timeOfDay ? clock(np.secondsOfDay, true) : fmt("%.1f", np.epochS));
        pg.text(x + 62, y, std::to_string(np.points));
        pg.text(x + 96, y, fmt("%.1f", np.rmsPs));
        pg.text(x + 136, y, fmt("%+.1f", np.meanResidualS * 1e12));
        pg.text(x + 188, y, std::isfinite(np.returnRatePct) ? fmt("%.1f", np.returnRatePct) : "–");
        if (station) {
            double delta = NAN;
            for (const NpDifference& row : c.station->rows)
                if (row.match == NpDifference::Match::Both && std::abs(row.ourT - np.epochS) < 0.5 * std::max(np.windowS, 1.0))
                    delta = row.deltaMm;
            pg.text(x + 228, y, std::isfinite(delta) ? fmt("%+.1f", delta) : "–");
        }
        y += rowH;
    }
    return y;
}

std::string productionDate() {
    std::time_t now = std::time(nullptr);
    if (const char* e = std::getenv("SOURCE_DATE_EPOCH")) {
        long long v = 0;
        if (parseLong(e, &v) && v >= 0) now = static_cast<std::time_t>(v);
    }
    std::tm tm{};
    char b[64] = "";
    if (gmtime_r(&now, &tm)) std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return b;
}

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

PassReport passReportOf(const SlrSetup& setup, const PassData& pass, const PassSettings& settings,
                        std::vector<std::string> notes) {
    const SlrSources& src = setup.sources;
    PassReport r;
    r.settings = &settings;
    for (const std::string* f : {&src.input, &src.cpf, &src.stations, &src.presets, &src.stationNormalPoints})
        if (!f->empty()) r.inputs.push_back(*f);
    r.notes = std::move(notes);
    r.stationFile = setup.stationNormalPoints;
    r.stationPath = src.stationNormalPoints;
    if (!src.input.empty())  // (a pass given as arrays has no command that reruns it)
        r.command = shellCommand(slrCommandArgs(src, pass.hasCrd ? pass.passIndex + 1 : 0, commandParams(setup, pass, settings.params)));
    return r;
}

bool passReportOfLoaded(const SlrSetup& run, const SlrSources& opened, const PassData& pass, const PassSettings& settings,
                        std::vector<std::string> notes, const std::string& stationNp, PassReport* out, SlrError* error) {
    SlrSetup s = run;
    if (!opened.cpf.empty()) {
        if (opened.stations == run.sources.stations) s.sources.cpf = opened.cpf;
        else notes.push_back("O-C from the prediction " + opened.cpf + " with the stations " + opened.stations +
                             ", which this run was not given: the command below has no prediction");
    }
    if (!stationNp.empty() && !setStationNormalPoints(&s, stationNp, error)) return false;
    *out = passReportOf(s, pass, settings, std::move(notes));
    return true;
}

bool writePassReport(const std::string& path, const PassData& pass, const PassRunResult& run, const PassReport& report,
                     std::string* error) {
    if (!report.settings) {
        *error = "the report needs the pass's parameters";
        return false;
    }
    std::string bytes;
    cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(appendBytes, &bytes, kPageW, kPageH);
    const std::string when = productionDate();
    const std::string what = passName(pass);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, ("SLR pass report: " + what).c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Laser Workbench " LWB_VERSION);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, when.c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_MOD_DATE, when.c_str());
    cairo_t* cr = cairo_create(surface);
    Page pg(cr);

    double ocSpan = 0;
    {
        const auto [lo, hi] = span(pass.oc, 0);
        ocSpan = hi - lo;
    }
    const bool us = ocSpan > 2e-6;
    // The station's normal points beside ours: the one comparison the Station NP tab shows.
    NpComparison compared;
    if (report.stationFile) {
        if (run.postOk) compared = compareWithStation(pass, run.post, *report.stationFile, report.stationPath);
        else compared.error = report.stationPath + ": no post-fit of the pass, so no normal points of ours to compare";
    }
    const NpComparison* stationNps = report.stationFile ? &compared : nullptr;
    const Context c{pass, run, report, stationNps, pass.hasCrd, us ? 1e-6 : 1e-9, us ? "µs" : "ns"};

    // ---- heading: what, where, when, and the verdict ----
    double y = kMargin + 10;
    const double x = kMargin, w = kPageW - 2 * kMargin;
    pg.font(13, true);
    pg.color(kInk);
    std::string sat = pass.satellite.empty() ? std::string("satellite unknown") : pass.satellite;
    if (!pass.ilrsId.empty()) sat += " (" + pass.ilrsId + ")";
    std::string station = pass.station.empty() ? std::string("station unknown") : pass.station;
    if (pass.cdpPad >= 0) station += " " + std::to_string(pass.cdpPad);
    pg.textFit(x, y, "SLR pass report — " + sat + " at " + station, w);
    y += 13;
    std::string day;
    if (pass.hasCrd && pass.crd && size_t(pass.passIndex) < pass.crd->passes.size()) {
        const CrdSession& h4 = pass.crd->passes[size_t(pass.passIndex)].session;
        char b[32];
        std::snprintf(b, sizeof b, "%04d-%02d-%02d", h4.startYear, h4.startMonth, h4.startDay);
        day = b;
    }
    double t0 = INFINITY, t1 = -INFINITY;
    for (double t : pass.t) t0 = std::min(t0, t), t1 = std::max(t1, t);
    pg.font(7.5);
    pg.color(kGrey);
    std::string sub = what + "; " + (day.empty() ? std::string() : day + " ") +
                      (c.timeOfDay && std::isfinite(t0) ? clock(t0, true) + "–" + clock(t1, true) + " UTC; " : std::string()) +
                      std::to_string(pass.t.size()) + " points; O-C: " + pass.ocOrigin;
    y = pg.paragraph(x, y, sub, w, 9, 2);
    const BlockStatus status = runStatus(pass, run);
    const bool good = status.status == "ok";
    pg.font(8.5, true);
    pg.color(good ? kOk : kRejected);
    std::string verdict = status.status;
    for (char& ch : verdict) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    pg.text(x, y + 1, verdict);
    const double vw = pg.width(verdict) + 6;
    pg.font(7.5);
    pg.color(kInk);
    std::string line = std::to_string(run.acceptedCount) + " of " + std::to_string(pass.t.size()) + " points accepted";
    if (run.postOk)
        line += ", " + std::to_string(run.post.stats.n) + " kept, post-fit RMS " + fmt("%.1f", run.post.stats.rms * 1e12) + " ps";
    if (run.agreement.available)
        line += "; against the station's flags: precision " +
                (std::isfinite(run.agreement.precision) ? fmt("%.3f", run.agreement.precision) : std::string("– (nothing accepted)")) +
                ", recall " + fmt("%.3f", run.agreement.recall);
    if (!status.reason.empty()) line += ". " + status.reason;
    y = pg.paragraph(x + vw, y + 1, line, w - vw, 9, 3);
    if (run.bias.ok) {
        pg.color(kGrey);
        y = pg.paragraph(x, y, "Against the prediction: " + describeBias(run.bias), w, 9, 1);
    }
    y += 14;

    // ---- the four plots ----
    const double gap = 52, pw = (w - gap - 30) / 2, ph = 150;
    drawOc(pg, c, Plot{x + 30, y, pw, ph, 0, 1, 0, 1});
    drawResiduals(pg, c, Plot{x + 30 + pw + gap, y, pw, ph, 0, 1, 0, 1});
    y += ph + 40;
    drawBinaryImage(pg, c, Plot{x + 30, y, pw, ph * 0.85, 0, 1, 0, 1});
    drawHistogram(pg, c, Plot{x + 30 + pw + gap, y, pw, ph * 0.85, 0, 1, 0, 1});
    y += ph * 0.85 + 36;

    // ---- parameters | normal points ----
    const double bottom = kPageH - kMargin - 92;
    const double colW = (w - 20) / 2;
    double yl = drawParameters(pg, c, x, y, colW);
    double yr = drawNormalPoints(pg, c, x + colW + 20, y, colW, bottom);
    y = std::max(yl, yr) + 6;

    // ---- station comparison, notes, provenance ----
    pg.rule(x, y, x + w, y, kLight, 0.5);
    y += 10;
    pg.font(6.5);
    if (stationNps) {
        pg.color(kInk);
        y = pg.paragraph(x, y, "Station normal points: " + (stationNps->ok ? stationNps->describe() : stationNps->error),
                         w, 8.2, 2);
    }
    for (const std::string& n : report.notes) {
        pg.color(kGrey);
        y = pg.paragraph(x, y, n, w, 8.2, 2);
    }
    for (const std::string& wmsg : run.screen.warnings) {
        pg.color(kGrey);
        y = pg.paragraph(x, y, "screening: " + wmsg, w, 8.2, 1);
    }
    y = std::max(y, kPageH - kMargin - 60);
    pg.font(7, true);
    pg.color(kInk);
    pg.text(x, y, "Provenance");
    y += 9;
    pg.font(6.2);
    for (const std::string& in : report.inputs) {
        if (in.empty()) continue;
        std::string hex, err;
        const std::string sum = sha256File(in, &hex, &err) ? "sha256 " + hex.substr(0, 16) + "…" : "not readable now";
        pg.color(kInk);
        pg.textFit(x, y, in + "  (" + sum + ")", w);
        y += 7.6;
    }
    if (!report.command.empty()) {
        pg.color(kGrey);
        pg.font(6, false, true);
        y = pg.paragraph(x, y, "laserwb-cli " + report.command, w, 7.4, 3);
    }
    pg.font(6);
    pg.color(kGrey);
    pg.text(x, kPageH - kMargin + 8, "Laser Workbench " LWB_VERSION ", written " + when + "; screening after paper 004 (docs/algorithms.md)");

    cairo_show_page(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t st = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (st != CAIRO_STATUS_SUCCESS) {
        *error = std::string("the PDF could not be drawn: ") + cairo_status_to_string(st);
        return false;
    }
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        *error = "cannot write " + path;
        return false;
    }
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !ok) {
        *error = "cannot write " + path + " (disk full?)";
        return false;
    }
    return true;
}

}  // namespace lwb::core::slr
