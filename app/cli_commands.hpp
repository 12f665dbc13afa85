#pragma once
// Entry points of the laserwb-cli subcommands; argv[1] (and argv[2] for two-word commands) is
// the command itself.
namespace lwb::cli {
int cmdFootprint(int argc, char** argv);
/// laserwb-cli footprint tune (cli_footprint.cpp).
int cmdFootprintTune(int argc, char** argv);
int cmdSimulateFootprint(int argc, char** argv);
int cmdTrend(int argc, char** argv);
int cmdSimulateTrend(int argc, char** argv);
int cmdEvalFootprint(int argc, char** argv);
int cmdBenchFootprint(int argc, char** argv);
// Altimeter calibration (paper 002) and radiometry (paper 003): app/cli_calib.cpp, app/cli_radiometry.cpp
int cmdCalibDetector(int argc, char** argv);
int cmdCalibWaveform(int argc, char** argv);
int cmdCalibPointing(int argc, char** argv);
int cmdCalibStats(int argc, char** argv);
int cmdSimulateCalib(int argc, char** argv);
int cmdRadiometryMosaic(int argc, char** argv);
int cmdRadiometryGcp(int argc, char** argv);
int cmdRadiometryFit(int argc, char** argv);
int cmdRadiometryApply(int argc, char** argv);
int cmdRadiometryCheck(int argc, char** argv);
int cmdSimulateRadiometry(int argc, char** argv);
// SLR signal extraction (paper 004): app/cli_slr.cpp, app/cli_slr_sim.cpp
int cmdSlr(int argc, char** argv);
/// laserwb-cli slr tune (cli_slr_tune.cpp).
int cmdSlrTune(int argc, char** argv);
int cmdSimulateSlr(int argc, char** argv);
int cmdBenchSlr(int argc, char** argv);
// CRD files: app/cli_crd.cpp ("crd check")
int cmdCrd(int argc, char** argv);
}  // namespace lwb::cli
