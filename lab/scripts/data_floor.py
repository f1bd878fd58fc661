"""What the single TrackMan drives allow: a regression floor, held out two ways.

Issues 34 and 35 (docs/impact.md §0.8, "What the data allow, held out the same way";
docs/aero.md, issue 35). The data README (`../shared/data/README.md`) quotes a
cross-validated gradient-boosted regression on `trackman_amateur_drives.csv` as "what the
data allow" without saying how it was cross-validated. This script measures that floor
under both

* **random 5-fold** cross-validation (rows shuffled with a fixed seed), and
* **leave-one-session-out**: the lab's sessions, blocks of 1,000 consecutive rows
  (`carry_lab::drives::SESSION_ROWS`; a row's session is its 0-based index among the data
  lines // 1,000), which is how our own held-out figures are measured,

on the same rows our lab examples use:

* ball data from club data — rows as `impact_single_shots` (`Drive::full_delivery` and
  `Drive::full_launch`: club speed, attack, path, dynamic loft and face present; ball
  speed, launch, direction, spin and axis present and plausible: ball speed 10–100 m/s,
  |angles| < 90°, spin 0–15,000 rpm). Inputs: club speed, attack, path, dynamic loft, face,
  face-to-path (face − path where the cell is empty); the second variant adds
  Impact Offset / Impact Height, scored on the rows that carry them (all of them in
  sessions 3 and 4), fitted either on those rows only or on every row with the location
  left empty where TrackMan has none (gradient boosting takes empty inputs as they are;
  the linear fit gets the training mean and a missing-indicator column).
* club data from ball data — rows as `estimate_single_shots` (the same selection).
  Inputs: ball speed, launch angle, launch direction, spin, spin axis, club speed.
* carry and total from the launch — rows as `aero_single_shots` (`drive_row`: full
  launch, launch ≥ 1°, carry > 0), premium ball, indoors (last tracked point ≤ 100 yd)
  and, apart, tracked outdoors (all in session 1: no session CV there). Inputs: the five
  launch numbers. `aero_single_shots` (and `spin_shape`, whose held-out carry docs/aero.md
  quotes) further drop the 49 rows whose carry `tour2023` misses by > 15 % (`SCREEN_PCT`);
  that screen needs the flight model, so this script takes it as a list of row indices
  (`--exclude=FILE`). The list was written by a throwaway example (not in the project):

      let all = drive_rows(&drives::read_shared()?, standard_air());
      let premium = premium_indoors(&all);
      let rows: Vec<_> = premium.iter().map(|r| r.row.clone()).collect();
      let pred = carries(&AeroModel::tour_2023(), &rows, &Integrator::dormand_prince(1e-9));
      let kept: HashSet<String> =
          screened(&premium, &pred).iter().map(|r| r.row.label.clone()).collect();
      // print `label` "drive N" → N − 1 for every premium row not in `kept` (49 rows)

Regressors: scikit-learn's `HistGradientBoostingRegressor` (squared error, otherwise
defaults; a quantity scored in % — ball speed, spin, carry, total — is fitted as its
logarithm, so the loss is about the squared relative error) with max_iter {100, 300} ×
learning_rate {0.05, 0.1} × max_leaf_nodes {15, 31} chosen by the least mean absolute
error of an inner cross-validation on the training folds only (inner folds of the same
kind as the outer: leave-one-session-out under session CV — shuffled 3-fold when the
training rows hold one session — and shuffled 3-fold under random CV), then refitted on
the whole training fold; and plain linear least squares (with an intercept, raw targets)
for reference. Mean absolute errors, prediction −
TrackMan; "%" errors are relative to TrackMan's value.

Run (not part of CI; reads the file where it lies, `$CARRY_DRIVES` overrides the path,
writes nothing; 22 min (1,329 s) at nice 5 on one core of the shared 2-core machine):

    python3 -m venv /tmp/floorvenv && /tmp/floorvenv/bin/pip install scikit-learn pandas numpy
    nice -n 5 /tmp/floorvenv/bin/python lab/scripts/data_floor.py [--exclude=FILE]

Options: `--quick` (one grid point, no inner CV: a smoke run); `--exclude=FILE` (0-based
row indices, whitespace-separated: the carry and total floors also on the premium indoor
rows less these, e.g. the rows `aero_single_shots` screens out).
"""

from __future__ import annotations

import math
import os
import sys
import time
from pathlib import Path

# One thread per fit: on a shared 2-core machine OpenMP threads contend (a 300-iteration fit
# took 0.55 s on one thread and 9 s on two under load).
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
from sklearn.ensemble import HistGradientBoostingRegressor  # noqa: E402
from sklearn.linear_model import LinearRegression  # noqa: E402
from sklearn.model_selection import KFold, LeaveOneGroupOut  # noqa: E402

SESSION_ROWS = 1000  # carry_lab::drives::SESSION_ROWS
OUTDOOR_TRACK_YD = 100.0  # carry_lab::drives::OUTDOOR_TRACK_M = 91.44 m
MPH_MPS = 0.44704
SEED = 0
GRID = {
    "max_iter": [100, 300],
    "learning_rate": [0.05, 0.1],
    "max_leaf_nodes": [15, 31],
}

COLUMNS = {
    "ball": "Ball",
    "club_speed": "Club Speed",
    "attack": "Attack Angle",
    "path": "Club Path",
    "loft": "Dyn. Loft",
    "face": "Face Angle",
    "ftp": "Face To Path",
    "ball_speed": "Ball Speed",
    "launch": "Launch Angle",
    "direction": "Launch Direction",
    "spin": "Spin Rate",
    "axis": "Spin Axis",
    "last_length": "Last data Point - Length",
    "carry": "Carry Flat - Length",
    "total": "Total",
    "toe": "Impact Offset",
    "height": "Impact Height",
}


def data_path() -> Path:
    env = os.environ.get("CARRY_DRIVES")
    if env:
        return Path(env)
    root = Path(__file__).resolve().parents[2]
    return root / ".." / "shared" / "data" / "trackman_amateur_drives.csv"


def number(cell: str) -> float:
    """A cell as `carry_lab::drives::parse` reads it: empty or non-finite is NaN."""
    cell = cell.strip()
    if not cell:
        return math.nan
    v = float(cell)
    return v if math.isfinite(v) else math.nan


def read(path: Path) -> dict[str, np.ndarray]:
    """The drives as columns (file units: mph, deg, rpm, yd, mm), with `index` and `session`
    as `carry_lab::drives` assigns them (blank lines keep their index, as there)."""
    lines = path.read_text().splitlines()
    header = [h.strip() for h in lines[0].split(",")]
    at = {k: header.index(v) for k, v in COLUMNS.items()}
    out: dict[str, list] = {k: [] for k in COLUMNS}
    out["index"] = []
    for index, line in enumerate(lines[2:]):
        if not line.strip():
            continue
        cells = [c.strip() for c in line.split(",")]
        get = lambda k: cells[at[k]] if at[k] < len(cells) else ""  # noqa: E731
        out["index"].append(index)
        out["ball"].append(get("ball"))
        for k in COLUMNS:
            if k != "ball":
                out[k].append(number(get(k)))
    cols = {k: np.asarray(v) for k, v in out.items()}
    cols["session"] = cols["index"] // SESSION_ROWS
    return cols


def present(*arrays: np.ndarray) -> np.ndarray:
    return np.logical_and.reduce([np.isfinite(a) for a in arrays])


def full_delivery(d) -> np.ndarray:
    return present(d["club_speed"], d["attack"], d["path"], d["loft"], d["face"])


def full_launch(d) -> np.ndarray:
    speed_mps = d["ball_speed"] * MPH_MPS
    ok = present(d["ball_speed"], d["launch"], d["direction"], d["spin"], d["axis"])
    with np.errstate(invalid="ignore"):
        return (
            ok
            & (speed_mps >= 10.0)
            & (speed_mps < 100.0)
            & (np.abs(d["launch"]) < 90.0)
            & (np.abs(d["direction"]) < 90.0)
            & (d["spin"] >= 0.0)
            & (d["spin"] < 15_000.0)
            & (np.abs(d["axis"]) < 90.0)
        )


def outdoors(d) -> np.ndarray:
    with np.errstate(invalid="ignore"):
        return np.nan_to_num(d["last_length"], nan=0.0) > OUTDOOR_TRACK_YD


def grid():
    keys = sorted(GRID)
    out = [{}]
    for k in keys:
        out = [dict(p, **{k: v}) for p in out for v in GRID[k]]
    return out


def boosted(params=None):
    return HistGradientBoostingRegressor(early_stopping=False, random_state=SEED,
                                         **(params or {}))


def tuned(x, y, inner, quick):
    """Gradient boosting with the grid point of least inner-CV mean absolute error (on the
    training rows only), refitted on all of them. An inner split whose training rows
    cannot be fitted (an input empty on every one of them: the strike location when the
    inner training sessions have none) is left out for every grid point alike."""
    if quick:
        return boosted().fit(x, y), None
    splits = [(tr, te) for tr, te in inner if not np.isnan(x[tr]).all(axis=0).any()]
    best, best_err = None, math.inf
    for params in grid():
        err = np.mean([np.mean(np.abs(boosted(params).fit(x[tr], y[tr]).predict(x[te]) - y[te]))
                       for tr, te in splits])
        if err < best_err:
            best, best_err = params, err
    return boosted(best).fit(x, y), best


def held_out(make, x, y, groups, scheme, quick, relative):
    """Held-out predictions of `make` under `scheme` ("session" or "random"), and the
    hyper-parameters each outer fold chose. A quantity scored relative to its value is
    fitted as its logarithm (squared error in log ≈ squared relative error)."""
    if relative and make == "hgb":
        pred, chosen = held_out(make, x, np.log(y), groups, scheme, quick, False)
        return np.exp(pred), chosen
    pred = np.full(len(y), np.nan)
    chosen = []
    if scheme == "session":
        outer = LeaveOneGroupOut().split(x, y, groups)
    else:
        outer = KFold(5, shuffle=True, random_state=SEED).split(x)
    for train, test in outer:
        if make == "linear":
            xl = x
            missing = np.isnan(x)
            if missing.any():  # empty cells: the training mean and a missing-indicator column
                fill = np.nanmean(x[train], axis=0)
                cols = missing.any(axis=0)
                xl = np.column_stack([np.where(missing, fill, x), missing[:, cols]])
            m = LinearRegression().fit(xl[train], y[train])
            pred[test] = m.predict(xl[test])
            continue
        else:
            xt, yt = x[train], y[train]
            if scheme == "session" and len(set(groups[train].tolist())) >= 2:
                inner = list(LeaveOneGroupOut().split(xt, yt, groups[train]))
            else:  # random CV, or one training session: shuffled folds inside it
                inner = list(KFold(3, shuffle=True, random_state=SEED).split(xt))
            m, p = tuned(xt, yt, inner, quick)
            if p:
                chosen.append(f"{p['max_iter']}/{p['learning_rate']}/{p['max_leaf_nodes']}")
        pred[test] = m.predict(x[test])
    return pred, chosen


def mae(pred, y, relative):
    e = pred - y
    if relative:
        e = 100.0 * e / y
    return float(np.mean(np.abs(e))), float(np.mean(e))


def run_block(d, mask, inputs, targets, quick, log, score=None):
    """Every target of `targets` ((name, column, relative)) from `inputs` on the rows of
    `mask`, both CVs, both regressors, scored on the rows of `score` (default: all of
    `mask`): {(scheme, model): {name: (mae, bias, pred, y, relative)}} (pred and y on the
    scored rows)."""
    x = np.column_stack([d[c] for c in inputs])[mask]
    groups = d["session"][mask]
    score = np.ones(mask.sum(), bool) if score is None else score[mask]
    out = {}
    for scheme in ("session", "random"):
        for model in ("hgb", "linear"):
            res = {}
            for name, col, rel in targets:
                y = d[col][mask]
                if scheme == "session" and len(set(groups.tolist())) < 2:
                    continue  # one session: nothing to hold out
                pred, chosen = held_out(model, x, y, groups, scheme, quick, rel)
                print(f"{name}, {mask.sum()} rows, {scheme}, {model}", file=sys.stderr, flush=True)
                pred, y = pred[score], y[score]
                res[name] = (*mae(pred, y, rel), pred, y, rel)
                if chosen:
                    log.append(f"{name} ({scheme}, {mask.sum()} rows): {', '.join(chosen)}")
            out[(scheme, model)] = res
    return out


def fmt(res, name, digits, pct, bias=False):
    if name not in res:
        return "n/a"
    m, b, *_ = res[name]
    s = f"{m:.{digits}f}{' %' if pct else '°'}"
    if bias:
        s += f" ({b:+.{min(digits, 2)}f} %)"
    return s


SCHEME = {"session": "by session (1,000-row blocks)", "random": "random 5-fold (seed 0)"}
MODEL = {"hgb": "gradient boosting", "linear": "linear least squares"}


def main() -> None:
    args = sys.argv[1:]
    quick = "--quick" in args
    exclude_name = next((a.split("=", 1)[1] for a in args if a.startswith("--exclude=")), None)
    t0 = time.perf_counter()
    d = read(data_path())
    d["face_to_path"] = np.where(np.isfinite(d["ftp"]), d["ftp"], d["face"] - d["path"])
    usable = full_delivery(d) & full_launch(d)
    located = usable & present(d["toe"], d["height"])
    n = len(d["index"])
    exclude = None
    if exclude_name:
        listed = {int(t) for t in Path(exclude_name).read_text().split()}
        exclude = np.isin(d["index"], sorted(listed))
        exclude_name = f"the {len(listed)} rows listed in {Path(exclude_name).name}"
    print(f"# What the data allow: {n} drives read, {usable.sum()} with club and ball data "
          f"({located.sum()} with the strike location, sessions "
          f"{sorted(set(d['session'][located].tolist()))})\n")
    if quick:
        print("(--quick: one grid point, no inner CV: not the committed figures)\n")
    log: list[str] = []

    club = ["club_speed", "attack", "path", "loft", "face", "face_to_path"]
    ball_targets = [
        ("ball speed", "ball_speed", True),
        ("launch", "launch", False),
        ("direction", "direction", False),
        ("spin", "spin", True),
        ("axis", "axis", False),
    ]
    loc = club + ["toe", "height"]
    # (label, fitted on, inputs, scored on)
    a_sets = [
        ("all, club data", usable, club, usable),
        ("with location, club data", located, club, located),
        ("with location, club data + location", located, loc, located),
        ("with location; fitted on all, + location where present", usable, loc, located),
    ]
    a_res = [(label, score, run_block(d, mask, inputs, ball_targets, quick, log, score))
             for label, mask, inputs, score in a_sets]

    print("## Ball data from club data (rows as `impact_single_shots`)\n")
    print("| rows | held out | regressor | ball speed | launch | direction | spin (bias) | axis |")
    print("|---|---|---|---:|---:|---:|---:|---:|")
    for label, mask, res in a_res:
        for key in [("session", "hgb"), ("random", "hgb"), ("session", "linear"), ("random", "linear")]:
            r = res[key]
            print(f"| {label} ({mask.sum()}) | {SCHEME[key[0]]} | {MODEL[key[1]]} | "
                  f"{fmt(r, 'ball speed', 1, True)} | {fmt(r, 'launch', 2, False)} | "
                  f"{fmt(r, 'direction', 2, False)} | {fmt(r, 'spin', 1, True, bias=True)} | "
                  f"{fmt(r, 'axis', 1, False)} |")

    print("\nPer held-out session (gradient boosting, session CV):\n")
    print("| rows | session | n | ball speed | launch | direction | spin (bias) | axis |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for label, mask, res in a_res:
        r = res[("session", "hgb")]
        sess = d["session"][mask]
        if not r:
            continue
        for s in sorted(set(sess.tolist())):
            k = sess == s
            cells = []
            for name, _, rel in ball_targets:
                _, _, pred, y, _ = r[name]
                m, b = mae(pred[k], y[k], rel)
                unit = " %" if rel else "°"
                digits = 1 if (rel or name == "axis") else 2
                cell = f"{m:.{digits}f}{unit}"
                if name == "spin":
                    cell += f" ({b:+.1f} %)"
                cells.append(cell)
            print(f"| {label} | {s} | {k.sum()} | " + " | ".join(cells) + " |")

    ball = ["ball_speed", "launch", "direction", "spin", "axis", "club_speed"]
    club_targets = [
        ("face", "face", False),
        ("path", "path", False),
        ("loft", "loft", False),
        ("attack", "attack", False),
    ]
    b_res = run_block(d, usable, ball, club_targets, quick, log)
    print("\n## Club data from ball data + club speed (rows as `estimate_single_shots`)\n")
    print("| rows | held out | regressor | face | path | dynamic loft | attack |")
    print("|---|---|---|---:|---:|---:|---:|")
    for key in [("session", "hgb"), ("random", "hgb"), ("session", "linear"), ("random", "linear")]:
        r = b_res[key]
        print(f"| {usable.sum()} | {SCHEME[key[0]]} | {MODEL[key[1]]} | "
              + " | ".join(fmt(r, t, 2, False) for t, _, _ in club_targets) + " |")
    print("\nPer held-out session (gradient boosting, session CV):\n")
    print("| session | n | face | path | dynamic loft | attack |")
    print("|---:|---:|---:|---:|---:|---:|")
    r = b_res[("session", "hgb")]
    sess = d["session"][usable]
    for s in sorted(set(sess.tolist())):
        k = sess == s
        cells = [f"{mae(r[t][2][k], r[t][3][k], False)[0]:.2f}°" for t, _, _ in club_targets]
        print(f"| {s} | {k.sum()} | " + " | ".join(cells) + " |")

    # Carry and total from the launch (rows as aero_single_shots' drive_row).
    with np.errstate(invalid="ignore"):
        aero = full_launch(d) & (np.nan_to_num(d["carry"], nan=0.0) > 0.0) & (d["launch"] >= 1.0)
    premium = d["ball"] == "Premium"
    launch_in = ["ball_speed", "launch", "direction", "spin", "axis"]
    print("\n## Carry and total from the launch (rows as `aero_single_shots`)\n")
    print("| rows | held out | regressor | carry (bias) | total (bias) |")
    print("|---|---|---|---:|---:|")
    indoor = aero & premium & ~outdoors(d)
    sets = [("premium, indoors", indoor)]
    if exclude is not None:
        sets.append((f"premium, indoors, less {exclude_name}", indoor & ~exclude))
    sets.append(("premium, tracked outdoors", aero & premium & outdoors(d)))
    for label, mask in sets:
        with_total = mask & np.isfinite(d["total"])
        res_c = run_block(d, mask, launch_in, [("carry", "carry", True)], quick, log)
        res_t = run_block(d, with_total, launch_in, [("total", "total", True)], quick, log)
        for key in [("session", "hgb"), ("random", "hgb"), ("session", "linear"),
                    ("random", "linear")]:
            print(f"| {label} ({mask.sum()}; total {with_total.sum()}) | {SCHEME[key[0]]} | "
                  f"{MODEL[key[1]]} | {fmt(res_c[key], 'carry', 2, True, bias=True)} | "
                  f"{fmt(res_t[key], 'total', 2, True, bias=True)} |")

    print("\nGrid choices (max_iter/learning_rate/max_leaf_nodes) per outer fold:\n")
    for line in log:
        print(f"- {line}")
    print(f"\n{time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
