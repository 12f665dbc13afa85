# %% [markdown]
# # Altimeter calibration: detector array, waveform, pointing and statistics
# Simulated calibration inputs (exact truth beside them), run through the core's calibration
# task (`laserwb-cli calib detector`, `calib waveform`, `calib pointing` and `calib stats`).

# %%
import os

import laserwb
from _inputs import simulate, workdir

work = workdir()
calib = os.path.join(work, "calib")
simulate("calib", "--seed", 5, calib)

# %% The footprint centre from the detector array
params = laserwb.calib.CalibParams()
print(params.describe("detector.outlier_sigma"))
d = laserwb.calib.detector(os.path.join(calib, "detectors.csv"), params=params)
print(d.centre, d.doubts or "not doubtful")
print(open(os.path.join(calib, "detector_truth.csv")).read().strip())
d.write_centre(os.path.join(work, "centre.csv"))

# %% The feature under the footprint: height from the double-peak waveform, matched to candidates
w = laserwb.calib.waveform(os.path.join(calib, "waveform.csv"), features=os.path.join(calib, "features.csv"))
print(f"height {w.waveform['height_m']:.3f} +- {w.waveform['height_sd_m']:.3f} m; match {w.match}")
print(open(os.path.join(calib, "waveform_truth.csv")).read().strip())
w.write_ranking(os.path.join(work, "ranking.csv"))

# %% Pointing and range calibration from the control points
x = laserwb.calib.pointing(os.path.join(calib, "control_points.csv"), os.path.join(calib, "beams.json"))
for b in x.beams:
    print(f"beam {b['id']}: d_alpha {b['d_alpha_rad'] * 1e6:.2f} urad, d_beta {b['d_beta_rad'] * 1e6:.1f} urad")
x.write_beams(os.path.join(work, "beams.csv"))

# %% Validation statistics per beam
s = laserwb.calib.stats(os.path.join(calib, "diffs.csv"), group="beam")
for name, g in s.groups().items():
    print(f"{name}: n {g['n']:.0f}, mean {g['mean']:.3f} m, RMS about zero {g['rms_about_zero']:.3f} m")
s.write_csv(os.path.join(work, "stats.csv"))
