# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Fitting the impact model by hand
#
# Paper 000's eq. (16) gives the impact tension of a link chain striking a
# pocket wheel, N_u = v_u sqrt(k q t E0 / (g L)), with the impact velocities
# of eqs. (1)-(2). This notebook reads the processed engagement demo
# (`chainbench run raw/engagement-demo`), fits the mass share k with lmfit by
# hand, and compares it with the pipeline's fit. Set `CHAINBENCH_PROCESSED`
# to read another processed folder.

# %%
import os
from pathlib import Path

import lmfit
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

from pipeline.theory import wheel_impact

processed = Path(os.environ.get("CHAINBENCH_PROCESSED", "../processed")) / "engagement-demo"
summary = xr.open_dataset(processed / "summary.nc")
points = summary[["teeth", "apex_angle", "omega", "N_u1_meas", "N_u2_meas", "N_u1_stderr",
                  "N_u2_stderr", "E0", "branch_length"]].to_dataframe()
points.head()

# %% [markdown]
# ## The model at every operating point, for a given k

# %%
t, d, mass_per_length = 0.064, 0.018, 6.6  # chain 18x64 (catalogue)


def model(k: float) -> tuple[np.ndarray, np.ndarray]:
    return wheel_impact.impact_tensions(
        t, d, points["teeth"].to_numpy(), np.radians(points["apex_angle"].to_numpy()),
        points["omega"].to_numpy(), mass_per_length, points["E0"].to_numpy(),
        points["branch_length"].to_numpy(), k=k)


# %% [markdown]
# ## Weighted least squares in k

# %%
def residual(params: lmfit.Parameters) -> np.ndarray:
    n1, n2 = model(params["k"].value)
    return np.concatenate([(points["N_u1_meas"] - n1) / points["N_u1_stderr"],
                           (points["N_u2_meas"] - n2) / points["N_u2_stderr"]])


params = lmfit.Parameters()
params.add("k", value=1.0, min=0.1, max=10)
result = lmfit.minimize(residual, params)
k_hand, k_hand_stderr = result.params["k"].value, result.params["k"].stderr
print(f"by hand: k = {k_hand:.4f} +- {k_hand_stderr:.4f} (reduced chi2 {result.redchi:.2f})")
print(f"pipeline: k = {float(summary['k_fit']):.4f} +- {float(summary['k_fit_stderr']):.4f}")

# %% [markdown]
# The pipeline scales the error by the Birge ratio when the points scatter more
# than their errors say; the value itself must agree:

# %%
assert abs(k_hand - float(summary["k_fit"])) < 1e-3 * float(summary["k_fit"])

# %% [markdown]
# ## N_u grows linearly with omega (eq. (16))

# %%
figure, axes = plt.subplots()
for z, group in points.groupby("teeth"):
    forty = group[group["apex_angle"].round() == 40]
    axes.errorbar(forty["omega"], forty["N_u2_meas"], yerr=forty["N_u2_stderr"], fmt="o",
                  label=f"N_u2 measured, z = {z}")
axes.set_xlabel("omega [1/s]")
axes.set_ylabel("impact tension N_u2 [N]")
axes.set_title("Impact tension on the working flank, apex angle 40 deg")
axes.legend()
