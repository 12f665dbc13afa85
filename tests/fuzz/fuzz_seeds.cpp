// Writes the generated seeds of the fuzz corpora: `fuzz_seeds OUTDIR` fills OUTDIR/<target>/
// with small valid inputs made by the project's own simulators and writers (the files the
// tests build from them), and the header and value variants the tests write by hand (column
// aliases, lat/lon instead of e/n, optional columns, quoting, comments, CRLF). Seeds from
// ../shared/data (CRD, CPF, SINEX) are added by make_seeds.sh. Everything is deterministic and
// small (a few hundred bytes to ~2 KiB), below the fuzzers' -max_len.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/calib/detector_array.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/pointing.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/trend.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/radiometry/reflectance.hpp"
#include "core/sim/calib_sim.hpp"
#include "core/sim/footprint_sim.hpp"
#include "core/sim/slr_sim.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"

namespace fs = std::filesystem;
using namespace lwb::core;

namespace {

fs::path g_out;
int g_written = 0;

fs::path target(const std::string& name) {
    const fs::path dir = g_out / name;
    fs::create_directories(dir);
    return dir;
}

void text(const std::string& tgt, const std::string& name, const std::string& content) {
    std::ofstream(target(tgt) / ("seed-" + name), std::ios::binary) << content;
    ++g_written;
}

// A file written by a project writer into the target's folder; false stops the run.
template <class Write>
void written(const std::string& tgt, const std::string& name, Write write) {
    std::string err;
    if (!write((target(tgt) / ("seed-" + name)).string(), &err)) {
        std::cerr << "fuzz_seeds: " << tgt << "/" << name << ": " << err << "\n";
        std::exit(1);
    }
    ++g_written;
}

void slrSeeds() {
    sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Khz);
    p.points = 40;
    p.durationS = 20;
    const sim::SlrSimPass pass = sim::simulateSlrPass(p, 7);
    slr::OcTable t;
    t.epoch_s = pass.epochS;
    t.oc_s = pass.ocS;
    text("oc_csv", "sim.csv", slr::formatOcCsv(t));
    text("oc_csv", "extra.csv",
         "epoch_s,oc_s,elevation_deg\n31787.7,1.5e-9,22.7\n31788.2,-2e-10,22.8\n# comment\n\"31788.7\",\"3e-10\",\"\"\n");
    text("oc_csv", "crlf-bom.csv", "\xEF\xBB\xBFOC_S,Epoch_S\r\n1e-9,1\r\n\r\n2e-9,2\r\n");
}

void calibSeeds() {
    sim::DetectorSimParams dp;
    dp.rows = 5;
    dp.columns = 5;
    const sim::DetectorSimulation ds = sim::simulateDetectorArray(dp, 11);
    written("detector_csv", "sim-enu.csv", [&](const std::string& f, std::string* e) {
        return calib::writeDetectorCsv(f, ds.array, e);
    });
    dp.geographic = true;
    dp.saturationLevel = 800;
    const sim::DetectorSimulation dg = sim::simulateDetectorArray(dp, 12);
    written("detector_csv", "sim-geo.csv", [&](const std::string& f, std::string* e) {
        return calib::writeDetectorCsv(f, dg.array, e);
    });
    text("detector_csv", "untriggered.csv", "id,e,n,energy,triggered\nA,0,0,,0\nB,5,5,12.5,1\nC,0,5,30,1\nD,5,0,9,1\n");
    text("detector_csv", "aliases.csv", "x,y,energy,height,saturated\n0,0,10,1000.5,0\n5,5,2e3,1001,1\n-5,0,7,999,0\n");

    sim::CalibSimParams cp;
    cp.passes = 2;
    const sim::CalibSimulation cs = sim::simulateCalibration(cp, 13);
    written("control_points_csv", "sim.csv", [&](const std::string& f, std::string* e) {
        return calib::writeControlPointCsv(f, cs.points, e);
    });
    text("control_points_csv", "latlon.csv",
         "beam,id,sat_x,sat_y,sat_z,q_w,q_x,q_y,q_z,range_m,gcp_lat,gcp_lon,gcp_h,sigma_h,sigma_v,use_height\n"
         "1,P1,-2062000,4945000,4688000,0.5,0.5,-0.5,0.5,500012.3,42.7,112.6,1000,0.5,0.05,1\n"
         "2,P2,-2062000,4945000,4688000,0.5,0.5,-0.5,0.5,500020.1,42.71,112.59,1003,,,0\n");
    written("beams_json", "gf7.json", [&](const std::string& f, std::string* e) {
        return writeFileAtomic(f, calib::beamsToJson(sim::gf7Beams()), e);
    });
    text("beams_json", "mounting.json",
         "{\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 90, \"offset_m\": [0.1, -0.2, 1.5],\n"
         "  \"mounting_quat\": [1, 0, 0, 0]}, {\"id\": 2, \"alpha_deg\": 0, \"beta_deg\": -90}]}\n");

    sim::WaveformSimParams wp;
    wp.samples = 40;
    wp.firstReturnNs = 5;
    wp.heightM = 2;
    const sim::WaveformSimulation ws = sim::simulateWaveform(wp, 14);
    std::string wave = "time_ns,amplitude\n", amp = "amplitude\n", sample = "sample,amplitude\n";
    for (size_t i = 0; i < ws.waveform.timeNs.size(); ++i) {
        wave += formatDouble(ws.waveform.timeNs[i], 6) + "," + formatFixed(ws.waveform.amplitude[i], 3) + "\n";
        amp += formatFixed(ws.waveform.amplitude[i], 2) + "\n";
        sample += std::to_string(i) + "," + formatFixed(ws.waveform.amplitude[i], 1) + "\n";
    }
    text("waveform_csv", "sim.csv", wave);
    text("waveform_csv", "amplitude.csv", amp);
    text("waveform_csv", "sample.csv", sample);
    text("feature_csv", "enu.csv", "id,e,n,h\nF1,1.50,-2.00,2.930\nF2,-12.25,4.00,5.1\nF3,0,0,0.3\n");
    text("feature_csv", "latlon.csv", "id,height,lat,lon\nA,2.9,42.7001,112.6002\nB,\"3.5\",42.7,112.6\n");
    text("feature_csv", "xy.csv", "# features\nid,x,y,h\r\nT1,10,20,4\r\n");
    text("differences_csv", "laser-control.csv",
         "beam,laser,control\n1,1046.096,1045.923\n2,1053.565,1053.690\n1,1043.427,1043.244\n");
    text("differences_csv", "d.csv", "d\n0.1\n-0.2\n0.05\n");
    text("differences_csv", "grouped.csv", "site,beam,dh\nlake,1,0.12\nlake,2,-0.08\nfield,1,0.3\n");
}

void footprintSeeds() {
    text("centroid_csv", "formats.csv",
         "time,beam,x,y,camera\n2020-03-02,1,57.18,313.10,LSI\n2020-03-15T10:22:01Z,2,228.01,156.67,LSI\n"
         "2020/04/15 10:22,1,57.3,313.0,LFI\n2020-05,2,228.1,156.5,LFI\n1593561600,1,57.2,313.2,LSI\n");
    text("centroid_csv", "nocamera.csv", "beam,time,y,x,note\n1,2021-01-01,20,10,a\n1,2021-02-01,20.5,10.1,\"b,c\"\n");
    text("shot_list", "gui.csv",
         "file,time,beam,camera,center_x,center_y\nm0/shot_000000.png,2021-03-10,1,LSI,60,311\n"
         "m0/shot_000000.png,2021-03-10T08:30:00Z,2,LSI,228,158\n/abs/f.tif,2021-04-01T12:00:00+02:00,1,LFI,,\n");
    text("shot_list", "plain.csv", "# file,time,beam\nfile,time,beam\r\na.png,1593561600,1\r\n\"b,c.png\",2020-05,2\r\n");
    const footprint::FootprintParams fp;
    text("footprint_config", "defaults.json", footprint::footprintParamsToJson(fp).dump());
    text("footprint_config", "partial.json", "{\"method\": \"gcm\", \"roi\": {\"size\": 40}}\n");
    text("footprint_config", "set-roi.txt", "roi.size=40");
    text("footprint_config", "set-preset.txt", "preset=yao2021");
    text("json", "footprint.json", footprint::footprintParamsToJson(fp).dump(-1));

    sim::FootprintSimParams sp;
    sp.width = sp.height = 12;
    const sim::FootprintSimShot shot = sim::simulateFootprint(sp, 15);
    for (const char* ext : {"png", "tif", "pgm"}) {
        for (const char* tgt : {"frame", "radiometry_image"})
            written(tgt, std::string("sim.") + ext, [&](const std::string& f, std::string* e) {
                return footprint::writeFrame16(f, shot.image, e);
            });
    }
    // Uncompressed PNG and TIFF: mutations then land on pixels and header fields, not on deflate/LZW.
    std::vector<uchar> buf;
    cv::imencode(".png", shot.image, buf, {cv::IMWRITE_PNG_COMPRESSION, 0});
    text("frame", "stored.png", std::string(buf.begin(), buf.end()));
    cv::imencode(".tif", shot.image, buf, {cv::IMWRITE_TIFF_COMPRESSION, 1});
    text("frame", "plain.tif", std::string(buf.begin(), buf.end()));
    // Raw as fuzz_frame reads it: width - 3, byte order, then little-endian pixels.
    std::string raw = {char(shot.image.cols - 3), 0};
    raw.append(reinterpret_cast<const char*>(shot.image.data), shot.image.total() * 2);
    text("frame", "sim.raw", raw);
    cv::Mat f32;
    shot.image.convertTo(f32, CV_32F, 1e-4);
    for (const char* tgt : {"frame", "radiometry_image"})
        written(tgt, "float.tif", [&](const std::string& f, std::string* e) {
            return radiometry::writeFloatTiff(f, f32, e);
        });
    cv::Mat u8, bgr;
    shot.image.convertTo(u8, CV_8U, 1.0 / 64);
    cv::merge(std::vector<cv::Mat>{u8, u8, u8}, bgr);
    cv::imencode(".png", u8, buf);
    text("radiometry_image", "grey8.png", std::string(buf.begin(), buf.end()));
    cv::imencode(".png", bgr, buf);
    text("radiometry_image", "colour.png", std::string(buf.begin(), buf.end()));
    cv::imencode(".jpg", bgr, buf);
    text("radiometry_image", "colour.jpg", std::string(buf.begin(), buf.end()));
}

void radiometrySeeds() {
    text("gcp_csv", "xy.csv", "id,x,y,map_x,map_y\nA,0,0,0,1.2\nB,299,0,2.99,1.2\nC,0,119,0,0.01\nD,150.5,60,1.5,0.6\n");
    text("gcp_csv", "colrow.csv", "col,row,X,Y\n0,0,500000.0,4700000.0\n100,0,500010,4700000\n0,100,500000,4699990\n");
    text("gcp_csv", "en.csv", "x,y,e,n\n1,2,3,4\n5,6,7,8\n9,10,11,12.5\n");
    text("region_csv", "rect.csv", "name,reflectance,x,y,w,h,role\npanel1,30,10,10,20,20,fit\npanel2,50.5,40,10,20,20,check\n");
    text("region_csv", "measured.csv", "name,measured,simulated\nok,30,30.3\nbad,10,11\n");
    text("region_csv", "dn.csv", "id,reflectance,dn\na,10,1000\nb,20,2000\nc,40,\"4000\"\n");
    text("region_csv", "mixed.csv", "region,reflectance_pct,mean_dn,simulated_pct,x,y,w,h\nr1,12,1500,,,,,\nr2,30,,,0,0,4,4\n");
    radiometry::ReflectanceFit fit;
    fit.k = 0.00123456789;
    fit.b = -1.5;
    fit.kSd = 1e-6;
    fit.bSd = 0.02;
    fit.covKB = -1e-8;
    fit.n = 5;
    fit.residualSd = 0.3;
    fit.r2 = 0.9991;
    fit.meanDn = 25000;
    written("fit_csv", "fit.csv", [&](const std::string& f, std::string* e) {
        return radiometry::writeFitCsv(f, fit, e);
    });
    text("fit_csv", "kb.csv", "k,b\n0.001,-2\n");
}

void jsonSeeds() {
    std::vector<slr::SatellitePreset> presets(2);
    presets[0].name = "lageos1";
    presets[0].ilrsId = "7603901";
    presets[0].postfit.altitudeKm = 5860;
    presets[1].name = "jason-3";
    presets[1].screen.automatic = true;
    const std::string doc = slr::presetsToJson(presets).dump();
    text("slr_presets", "two.json", doc);
    text("slr_config", "defaults.json", slr::slrSchema().toJson(slr::SlrParams{}).dump(1));
    text("slr_config", "partial.json", "{\"screen\": {\"cosine_c\": 0.97, \"automatic\": true}}\n");
    text("slr_config", "set-cosine.txt", "screen.cosine_c=0.97");
    text("slr_config", "set-auto.txt", "screen.area_limit=auto");
    text("calib_config", "defaults.json", calib::calibSchema().toJson(calib::CalibParams{}).dump(1));
    text("calib_config", "set-trigger.txt", "detector.trigger=50");
    text("calib_config", "partial.json", "{\"detector\": {\"noise\": \"given\", \"model\": \"circular\"}}\n");
    text("radiometry_config", "defaults.json", radiometry::radiometrySchema().toJson(radiometry::RadiometryParams{}).dump(1));
    text("radiometry_config", "set-model.txt", "gcp.model=affine");
    text("trend_config", "defaults.json", footprint::trendSchema().toJson(footprint::TrendParams{}).dump(1));
    text("slr_presets", "minimal.json",
         "{\"format\": \"laserwb-slr-presets\", \"version\": 1, \"satellites\": [{\"ilrs_id\": \"1\"}]}");
    text("json", "presets.json", doc);
    text("json", "beams.json", calib::beamsToJson(sim::gf7Beams()));
    text("json", "values.json",
         "{\"a\": [1, -0.5, 2.5e-3, 1E+2, 0, -0], \"s\": \"q\\\"\\\\\\/\\b\\f\\n\\r\\t\\u00e9\\ud83d\\ude00\",\n"
         " \"n\": null, \"t\": true, \"f\": false, \"o\": {\"deep\": [[[{}]]]}, \"e\": [], \"u\": \"\xc3\xa9\"}\n");
    // A session: format, version and the three parameter blocks (values within range).
    text("session", "params.lwb.json",
         "{\"format\": \"laserwb-session\", \"version\": 1, \"workspace\": \"calibration\",\n"
         " \"footprint\": {\"params\": " + footprint::footprintParamsToJson(footprint::FootprintParams()).dump(-1) + "},\n"
         " \"calibration\": {\"params\": {\"detector\": {\"model\": \"circular\", \"fit_background\": false,\n"
         "   \"background\": 0, \"trigger\": 50, \"saturation\": 0, \"rel_noise\": 0.05, \"noise_floor\": 2,\n"
         "   \"scale_chi2\": true}, \"pointing\": {\"model\": \"dual\", \"solve_range\": true, \"fix_relative\": false,\n"
         "   \"sigma_h\": 0.5, \"sigma_v\": 0.05, \"sigma_range\": 0.1, \"sigma_attitude_urad\": 1, \"sigma_orbit\": 0.05,\n"
         "   \"scale_chi2\": true}, \"waveform\": {\"sample_interval_ns\": 0.5, \"smooth_ns\": 1,\n"
         "   \"min_separation_ns\": 3, \"min_second_peak\": 0.1, \"incidence_deg\": 0, \"thred_h\": 0.1}}},\n"
         " \"radiometry\": {\"params\": {\"dn_min\": 100, \"dn_max\": 60000, \"exclude_out_of_range\": true,\n"
         "   \"vm_pct\": 0.17, \"nan_out_of_range\": false, \"uncertainty_image\": true, \"limit_pct\": 5,\n"
         "   \"mosaic\": {\"features\": \"akaze\", \"model\": \"similarity\", \"blend\": \"feather\",\n"
         "   \"ransac_px\": 3, \"min_inliers\": 12}}}}\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: fuzz_seeds OUTDIR\n";
        return 2;
    }
    g_out = argv[1];
    slrSeeds();
    calibSeeds();
    footprintSeeds();
    radiometrySeeds();
    jsonSeeds();
    std::cout << "fuzz_seeds: wrote " << g_written << " seeds under " << g_out.string() << "\n";
    return 0;
}
