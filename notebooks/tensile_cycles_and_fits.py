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
# # A tensile run: its cycles, its fits and the chain's stiffness
#
# Reads the processed stiffness demo (`chainbench run raw/stiffness-demo`) through
# xarray: one run's load cycles, the stiffness fitted on each loading and
# unloading branch, and the chain table with the theory of Paper 001 beside.
# Set `CHAINBENCH_PROCESSED` to read another processed folder.

# %%
import os
from pathlib import Path

import matplotlib.pyplot as plt
import xarray as xr

processed = Path(os.environ.get("CHAINBENCH_PROCESSED", "../processed")) / "stiffness-demo"
run = xr.open_dataset(processed / "T18-A.nc")
summary = xr.open_dataset(processed / "summary.nc")
print(run.attrs["title"], "|", run.attrs["source"])

# %% [markdown]
# ## Force over strain, cycle by cycle
# Cycle 1 seats the links (slack take-up at low load); E0 counts cycles 2..n.

# %%
figure, axes = plt.subplots()
for cycle in range(1, int(run["sample_cycle"].max()) + 1):
    chosen = run["sample_cycle"] == cycle
    axes.plot(1e3 * run["strain"][chosen], run["force"][chosen] / 1e3, label=f"cycle {cycle}")
axes.set_xlabel("strain [10^-3]")
axes.set_ylabel("force [kN]")
axes.set_title(f"Run {run.attrs['run_id']}, specimen {run.attrs['specimen']}")
axes.legend()

# %% [markdown]
# ## The fits per cycle and branch
# Each branch is fitted in its own window (least normalised residual); the
# interval widens the OLS error for autocorrelated residuals.

# %%
fits = run[["fit_E0", "fit_E0_stderr", "fit_window_low", "fit_window_high", "fit_r2"]]
table = fits.to_dataframe().dropna()
table["E0 [kN]"] = table["fit_E0"] / 1e3
table["stderr [%]"] = 100 * table["fit_E0_stderr"] / table["fit_E0"]
table[["E0 [kN]", "stderr [%]", "fit_r2"]]

# %% [markdown]
# The specimen's E0 is the mean of the loading branches of cycles 2..n:

# %%
loading = run["fit_E0"].sel(branch="loading").sel(cycle=slice(2, None))
by_hand = float(loading.mean())
print(f"by hand: {by_hand / 1e3:.1f} kN, stored: {float(run['specimen_E0']) / 1e3:.1f} kN")
assert abs(by_hand / float(run["specimen_E0"]) - 1) < 1e-12

# %% [markdown]
# ## The chain table: experiment against eq. (20)

# %%
columns = ["E0_exp", "E0_exp_ci_low", "E0_exp_ci_high", "E0_theory", "discrepancy", "in_band"]
chains = summary[columns].to_dataframe()
chains[["E0_exp", "E0_exp_ci_low", "E0_exp_ci_high", "E0_theory"]] /= 1e3  # kN
chains["discrepancy"] *= 100  # %
chains
