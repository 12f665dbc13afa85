#pragma once
// Entry points of the laserwb-cli subcommands; argv[1] (and argv[2] for two-word commands) is
// the command itself.
namespace lwb::cli {
int cmdFootprint(int argc, char** argv);
int cmdSimulateFootprint(int argc, char** argv);
int cmdTrend(int argc, char** argv);
int cmdEvalFootprint(int argc, char** argv);
int cmdBenchFootprint(int argc, char** argv);
}  // namespace lwb::cli
