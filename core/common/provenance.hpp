#pragma once
// Provenance of a command's outputs: which program and version wrote them, with which
// parameters (the schema's JSON, as --print-config writes it) and other settings, from which
// inputs (SHA-256 of each), and the SHA-256 of every output written. It is written beside the
// outputs as a sidecar, OUT.provenance.json for an output file named on the command line and
// DIR/provenance.json for an output folder, in the same OutputSet (all or nothing with them).
// A sidecar rather than a comment header: the project's CSV reader skips '#' lines, but
// spreadsheets, pandas' read_csv and most other readers do not, and a CRD's records have no room
// for a parameter set (its C5 software record names the program and version, and ours write it).
// Reproducible: no clock, no host or user names; the same command on the same inputs writes the
// same bytes.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/json.hpp"
#include "core/common/output_set.hpp"

namespace lwb::core {

struct Provenance {
    std::string command;                   ///< e.g. "footprint", "slr --all-passes"
    Json parameters = Json::object();      ///< the schema's JSON of the parameters used
    Json settings = Json::object();        ///< other settings that shape the outputs (centres, shard, ...)
    std::vector<std::string> inputs;       ///< the files read, as named (duplicates dropped)
};

/// The sidecar of an output file.
inline std::string provenancePathFor(const std::string& output) { return output + ".provenance.json"; }

/// The sidecar's JSON text: software, version, command, parameters, settings, inputs with their
/// SHA-256, and outputs (`outputs`: the names to record, `files`: where their bytes are now,
/// e.g. the staged copies; the same size) with theirs. Standard input ("-") and folders are
/// listed without a checksum (null). False with *error when a file cannot be read.
bool provenanceText(const Provenance& p, const std::vector<std::string>& outputs, const std::vector<std::string>& files,
                    std::string* text, std::string* error);

/// How a sidecar names an output: by its file name when they share a folder (so that the folder
/// can be moved or copied whole), else as given ("./" before a bare name).
std::string recordedName(const std::string& output, const std::string& sidecar);

/// Stages the provenance sidecar `sidecar` of the run's outputs `outputs` (already staged in
/// `outs`; `sidecar` added to it before check()). An output in the sidecar's folder is named
/// by its file name (the folder can be moved whole), another as given. False with *error.
bool stageProvenance(OutputSet& outs, const Provenance& p, const std::vector<std::string>& outputs,
                     const std::string& sidecar, std::string* error);

/// Writes one file and, beside it, its provenance, all or nothing: `write(stagingPath, &error)`
/// writes the file's bytes where the OutputSet stages it; the inputs of `p` are registered (the
/// file may replace none of them), the sidecar (provenancePathFor) lists the file with its
/// SHA-256, and both are renamed into place together. Standard output ("-") gets the file alone.
/// False with *error (naming the file) and nothing written. (A result's writer from Python.)
/// `update`: the file was read by the run and is replaced on purpose (OutputSet::addUpdate: an
/// existing presets file that gets an entry).
bool writeWithProvenance(const Provenance& p, const std::string& path,
                         const std::function<bool(const std::string&, std::string*)>& write, std::string* error,
                         bool update = false);

}  // namespace lwb::core
