# %% [markdown]
# # Long-term pointing from spot centroids
# A simulated centroid table of two beams over 12 months (exact monthly centres in the truth
# file), reduced to the monthly trend by the core (`laserwb-cli trend`).

# %%
import csv
import os

import laserwb
from _inputs import simulate, workdir

work = workdir()
table = os.path.join(work, "centroids.csv")
simulate("trend", "--months", 12, "--seed", 4, table, "--truth", os.path.join(work, "truth.csv"))

# %%
t = laserwb.trend.compute(table, params=laserwb.trend.TrendParams({"reject_sigma": 2.5}))
c = t.columns()
for i in range(len(t)):
    print(f"beam {c['beam'][i]} {c['month'][i]}: x {c['x_mean'][i]:.3f} y {c['y_mean'][i]:.3f} px, "
          f"change {c['pointing_change_arcsec'][i]:.3f} arcsec")

# %% Against the truth
truth = {(r["beam"], r["month"]): r for r in csv.DictReader(open(os.path.join(work, "truth.csv")))}
worst = max(abs(c["x_mean"][i] - float(truth[(c["beam"][i], c["month"][i])]["x_true"])) for i in range(len(t)))
print(f"largest error of a monthly mean: {worst:.3f} px")
t.write_csv(os.path.join(work, "trend.csv"))
