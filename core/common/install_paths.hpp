#pragma once
// Where the programs find what is installed beside them. The same binaries run from the build
// tree (build/bin: everything in one folder) and from an installation (cmake --install, the .deb):
//   PREFIX/bin/laserwb, PREFIX/bin/laserwb-cli
//   PREFIX/libexec/laserwb/laserwb-cli-imaging, PREFIX/libexec/laserwb/liblaserwb_codecs.so
//   PREFIX/share/laserwb/terrain/ (the footprint simulator's photographs)
// Paths are found relative to the running executable, so an installation can be moved.
#include <string>
#include <vector>

namespace lwb::core {

/// The folder of the running executable (from /proc/self/exe), or "" when unknown.
std::string executableDir();

/// Where a helper that an installation puts in libexec/laserwb may be, most likely first:
/// beside the executable (build tree, or an installed helper itself), then
/// ../libexec/laserwb/NAME (an installed program in bin/).
std::vector<std::string> helperCandidates(const std::string& name);

/// Where the installed data folder share/laserwb/SUB may be for this executable: from bin/
/// (../share/laserwb/SUB) and from libexec/laserwb/ (../../share/laserwb/SUB).
std::vector<std::string> installedDataCandidates(const std::string& sub);

}  // namespace lwb::core
