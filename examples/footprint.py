# %% [markdown]
# # Footprint spot centres from Python
# Simulated footprint-camera shots (exact truth in truth.csv), fitted by the core's footprint
# task (the same as `laserwb-cli footprint`), as numpy arrays in and a report out.

# %%
import csv
import os

import numpy as np

import laserwb
from _inputs import simulate, workdir

work = workdir()
shots = os.path.join(work, "shots")
simulate("footprint", "--count", 16, "--seed", 1, shots)
files = sorted(os.path.join(shots, f) for f in os.listdir(shots) if f.endswith(".png"))

# %% One ROI: a float32 array in, the report's row out
roi = laserwb.footprint.read_frame(files[0])
row = laserwb.footprint.fit(roi)
print(f"{os.path.basename(files[0])}: x {row['x']:.3f}, y {row['y']:.3f} px, {row['verdict']}, snr {row['snr']}")

# %% A batch: a 3-D stack (viewed, not copied), parameters by key
stack = np.stack([laserwb.footprint.read_frame(f) for f in files])
params = laserwb.footprint.FootprintParams({"segment.threshold_factor": 0.25})
report = laserwb.footprint.fit_batch(stack, params=params, names=files)
cols = report.columns()
print(f"{len(report)} ROIs: {np.sum(cols['verdict'] == 'good')} good")

# %% Against the truth
truth = {r["file"]: r for r in csv.DictReader(open(os.path.join(shots, "truth.csv")))}
err = [np.hypot(x - float(truth[os.path.basename(f)]["x"]), y - float(truth[os.path.basename(f)]["y"]))
       for f, x, y, v in zip(cols["file"], cols["x"], cols["y"], cols["verdict"]) if v == "good"]
print(f"radial error of the good shots: median {np.median(err):.3f} px, max {np.max(err):.3f} px")

# %% The report, written by the CLI's writer
report.write_csv(os.path.join(work, "report.csv"))
print("->", os.path.join(work, "report.csv"))
