// libFuzzer target: the beam-design JSON of the pointing calibration (calib pointing --beams,
// the calibration workspace). A failed read says why; beams that read are written (beamsToJson,
// as --beams-out does) and read again with the same ids.
#include "core/calib/pointing.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<BeamDesign> beams;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "json", readBeamsJson, &beams)) return 0;
    std::vector<BeamDesign> back;
    std::string err;
    check(readBeamsJson(lwb::fuzz::inputFile(beamsToJson(beams), "json"), &back, &err));
    check(back.size() == beams.size());
    for (size_t i = 0; i < beams.size(); ++i) check(back[i].id == beams[i].id);
    return 0;
}
