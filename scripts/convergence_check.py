#!/usr/bin/python3
"""The main answers of a scene with their numerical uncertainty: a grid-convergence band.

usage: /usr/bin/python3 scripts/convergence_check.py SCENE --out DIR [--np N] [--levels 2|3]
           [--refine h|p] [--companion coarser|finer] [--third coarser|finer]
           [--degrees P2[,P3]] [--axes x,y] [--geo FILE.geo [--geo-set N=V,...] [--geo-dim 2|3]]
           [--order Q] [--interface base] [--reuse] [--echo-main] [-- SLIPWAVE OPTIONS...]

Runs slipwave on the scene (options file SCENE, then the options after `--`) at its own
resolution, the main run, in DIR/main, and at a companion resolution in DIR/coarse (or
DIR/fine); with --levels 3 a third level one more step away on the side --third names
(DIR/coarser or DIR/finer). Each run is `$MPIEXEC $MPIEXEC_FLAGS -n N build/slipwave ...`
as `make run` launches it (MPIEXEC defaults to mpiexec; MPIEXEC_FLAGS to --oversubscribe,
and --allow-run-as-root for root; SLIPWAVE to build/slipwave), its log in DIR/<level>.log
and its command in DIR/<level>.command (--reuse keeps a level whose command is the same).
Nothing is written outside DIR.

Levels. --refine h (the default) halves (coarser) or doubles (finer) -mesh_box_faces along
the axes --axes names (default all), so the refinement ratio of the cell size is r = 2; the
stable step follows the cells. Every region box must lie on the cell edges of every level:
a box edge through cells would change the scene's geometry with the level. --companion and
--third auto (the default) take the coarser side where the scene allows it and the finer
one otherwise, and say so (the default scene's 6 m block at x = -3..3 m does not fit the
2 m cells of its coarse level; its finer level costs 8 times the main run in 2D). --refine p
changes -element_degree on the same elements instead: the levels' degrees are the scene's
and --degrees (e.g. --degrees 1 for a scene at p = 2); r is the ratio of the degrees, the
ratio of the mean GLL node spacings. A Gmsh mesh: --refine h with --geo FILE.geo meshes every
level from that file, `gmsh -2 FILE.geo -clscale 2^-k -setnumber N V ... -format msh41` (the
main run 1, the coarse level 2, a finer level 1/2: Gmsh scales every size the file sets,
its size fields included; a structured file can scale its counts by Mesh.MeshSizeFactor,
tests/data/column.geo) into DIR/<level>.msh, and runs it as the level's -mesh_file; r = 2,
the size factor's ratio (the cell counts, printed, show how the file followed it). --geo-set
sets the file's numbers, --geo-dim the mesh's dimension (default 2); the companion is then
coarser unless --companion says finer. A scene whose mesh_file has its .geo beside it
(config/scenes/default.msh and default.geo) takes that file without --geo.

Answers. scripts/scene_metrics.py on every level. The low-passed peaks are all taken at the
coarsest level's resolved frequency, so that the levels low-pass alike and their peaks are
one quantity. The high-frequency shares and the frequencies are reported, not banded (they
describe the mesh, they do not converge to an answer).

The band (Roache 1994, J. Fluids Eng. 116, 405-413; the procedure of Celik et al. 2008,
J. Fluids Eng. 130, 078001). With values f1 (finest), f2, f3 (coarsest) and ratios
r21 = h2/h1, r32 = h3/h2:
- three levels whose differences e21 = f2 - f1 and e32 = f3 - f2 have one sign and shrink
  (|e21| < |e32|): the observed order p solves p = |ln|e32/e21| + ln((r21^p - s)/(r32^p - s))|
  / ln r21 with s = sign(e32/e21) (fixed point; p = ln(e32/e21)/ln r when r21 = r32), and
  Fs = 1.25. An observed order above the formal one (--order) is not taken: the formal is
  used (the band is then wider; the 1D column at 200-400-800 cells observes 2.60 where its
  error falls at 2.25, and the band with 2.60 would miss the exact value);
- two levels, or three that oscillate or do not converge: the formal order --order (default
  1, what a scene with contact, impacts and sliding is assumed to reach) and Fs = 3; with
  three levels the band is at least the spread of the three values, and the note says why;
- the Richardson estimate f_ext = f1 + (f1 - f2) / (r21^p - 1), and the band of the main
  run's value f_main: Fs |f_main - f_ext|. With the main run the finest level this is
  Roache's GCI of the fine grid, Fs |f1 - f2| / (r^p - 1); with it the middle level, his
  GCI of the coarse grid, Fs |f1 - f2| r^p / (r^p - 1).

Output: DIR/main/convergence.json (every level's options and answers, and for each banded
answer the main value, band, relative band, order used and whether observed, safety factor,
Richardson estimate and note), the same as the key "convergence" of DIR/main/run_info.json,
and a table on stdout, then the answers sorted by their band: within 5 % of the value (issue
21's bound), and wider (each with its band), and those that are zero on the main level.
"""
import argparse
import json
import math
import os
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, ".."))
sys.path.insert(0, HERE)
import scene_metrics  # noqa: E402

# Answers reported for the mesh, not banded.
NOT_BANDED_PREFIXES = ("high_frequency_share_",)
NOT_BANDED = ("resolved_frequency_hz", "lowpass_frequency_hz")
FS_THREE, FS_TWO = 1.25, 3.0  # Roache's safety factors for three and for two levels


def fail(message):
    raise SystemExit(f"convergence_check: error: {message}")


# ---------------------------------------------------------------- the band


def observed_order(e21, e32, r21, r32):
    """The observed order of three monotonically converging values (Celik et al. 2008, eq. 3-5):
    the fixed point of p = |ln|e32/e21| + q(p)| / ln r21, q(p) = ln((r21^p - s)/(r32^p - s)),
    s = sign(e32/e21); None when e21, e32 differ in sign or do not shrink."""
    if e21 == 0 or e32 == 0 or e32 / e21 <= 0 or abs(e21) >= abs(e32):
        return None
    s = 1.0
    p = math.log(abs(e32 / e21)) / math.log(r21)
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        p_new = abs(math.log(abs(e32 / e21)) + q) / math.log(r21)
        if abs(p_new - p) < 1e-12:
            return p_new
        p = p_new
    return p


def grid_band(values, ratios, formal_order, main=0):
    """The grid-convergence band of one answer.

    values: the answer on each level, finest first (f1, f2[, f3]); ratios: the refinement
    ratios between consecutive levels, h2/h1[, h3/h2], each > 1; formal_order: the order
    assumed where none is observed; main: the index in values of the run whose value is
    banded. Returns a dict: value, band (absolute, >= 0), relative_band (band / |value|, None
    for a value 0), order (used), order_observed (or None), safety_factor, extrapolated (the
    Richardson estimate), note."""
    if len(values) not in (2, 3) or len(ratios) != len(values) - 1:
        raise ValueError("grid_band takes 2 or 3 values and one ratio fewer")
    if min(ratios) <= 1:
        raise ValueError("refinement ratios must be > 1")
    f = [float(v) for v in values]
    r21 = ratios[0]
    p_obs = None
    note = ""
    if len(f) == 3:
        e21, e32 = f[1] - f[0], f[2] - f[1]
        if e21 == 0 and e32 == 0:
            note = "the same on every level"
        else:
            p_obs = observed_order(e21, e32, r21, ratios[1])
            if p_obs is None:
                note = "oscillates between the levels" if e21 * e32 < 0 else "does not converge (the finer pair differs more)"
    if p_obs is not None:
        order, fs = min(p_obs, formal_order), FS_THREE
        if p_obs > formal_order:
            note = f"observed order {p_obs:.2f} above the formal {formal_order:g}: the formal used"
    else:
        order, fs = formal_order, FS_TWO
    extrapolated = f[0] + (f[0] - f[1]) / (r21 ** order - 1)
    band = fs * abs(f[main] - extrapolated)
    if len(f) == 3 and p_obs is None and note != "the same on every level":
        band = max(band, max(f) - min(f))
    value = f[main]
    return {"value": value, "band": band, "relative_band": band / abs(value) if value != 0 else None,
            "order": order, "order_observed": p_obs, "safety_factor": fs, "extrapolated": extrapolated, "note": note}


# ---------------------------------------------------------------- the scene and its levels


def read_options_file(path):
    """{name without '-': value} of a slipwave options file (flat YAML `name: value` lines)."""
    options = {}
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        fail(f"SCENE {path}: {e.strerror}; allowed: a readable slipwave options file")
    for line in lines:
        text = line.split("#", 1)[0].strip()
        if not text or ":" not in text:
            continue
        name, value = text.split(":", 1)
        options[name.strip().lstrip("-")] = value.strip().strip("'\"")
    return options


def command_line_options(words):
    """{name: value} of slipwave options given as -name value words (a flag alone: 'true')."""
    options = {}
    i = 0
    while i < len(words):
        word = words[i]
        if word.startswith("-") and not _is_number(word):
            name = word.lstrip("-")
            if i + 1 < len(words) and (not words[i + 1].startswith("-") or _is_number(words[i + 1])):
                options[name] = words[i + 1]
                i += 2
                continue
            options[name] = "true"
        i += 1
    return options


def _is_number(word):
    try:
        float(word.split(",")[0])
        return True
    except ValueError:
        return False


def without_options(words, names):
    """The words with the options `names` (and their values) left out."""
    out, i = [], 0
    while i < len(words):
        if words[i].lstrip("-") in names and words[i].startswith("-"):
            i += 2 if i + 1 < len(words) and (not words[i + 1].startswith("-") or _is_number(words[i + 1])) else 1
            continue
        out.append(words[i])
        i += 1
    return out


def numbers(text, option, count=None):
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        fail(f"-{option} {text}: not a list of numbers; allowed: comma-separated numbers")
    if count is not None and len(values) != count:
        fail(f"-{option} {text}: {len(values)} values; allowed: {count}")
    return values


LEVEL_NAMES = {0: "main", -1: "coarse", -2: "coarser", 1: "fine", 2: "finer"}


def ladder(companion, third, levels):
    """The levels as steps from the main run (0; -k: k times coarser, +k: k times finer),
    finest first."""
    steps = [0, -1 if companion == "coarser" else 1]
    if levels == 3:
        steps.append(min(steps) - 1 if third == "coarser" else max(steps) + 1)
    return sorted(steps, reverse=True)


def box_levels(options, args, steps):
    """[(name, options, h relative to the main run)] of the h levels `steps`, and why they do
    not fit the scene (None when they do)."""
    faces = numbers(options["mesh_box_faces"], "mesh_box_faces")
    axes = list(range(len(faces))) if args.axes is None else ["xyz".index(a) for a in args.axes.split(",") if a and a in "xyz"]
    if args.axes is not None and (not axes or any(a >= len(faces) for a in axes) or len(axes) != len(args.axes.split(","))):
        fail(f"--axes {args.axes}; allowed: a comma list of x, y (, z in 3D) among the {len(faces)} axes of -mesh_box_faces")
    levels = []
    for k in steps:
        scaled = list(faces)
        for a in axes:
            n = faces[a] * 2.0 ** k
            if n < 1 or n != int(n):
                return None, (f"-mesh_box_faces {options['mesh_box_faces']}: {int(faces[a])} cells along {'xyz'[a]} cannot be halved {-k} time(s) for the "
                              f"{LEVEL_NAMES[k]} level; allowed: counts divisible by {2 ** -k} on every axis --axes names (default all; a column: --axes y)")
            scaled[a] = n
        levels.append((LEVEL_NAMES[k], ["-mesh_box_faces", ",".join(str(int(n)) for n in scaled)], 2.0 ** -k))
    return levels, region_boxes_misfit(options, [(name, numbers(extra[1], "mesh_box_faces")) for name, extra, _ in levels])


def levels_of(options, args):
    """[(name, extra options, resolution h relative to the main run)], finest first, and the
    index of the main run in it. With --companion or --third auto, the coarser side where
    the levels fit the scene, else the finer (said on stdout)."""
    if args.refine == "h" and args.geo:
        steps = ladder("finer" if args.companion == "finer" else "coarser", "finer" if args.third == "finer" else "coarser", args.levels)
        return [(LEVEL_NAMES[k], ["-mesh_file", os.path.join(args.out, f"{LEVEL_NAMES[k]}.msh")], 2.0 ** -k) for k in steps], steps.index(0)
    if args.refine == "h":
        if "mesh_box_faces" not in options:
            fail(f"SCENE {args.scene} has no mesh_box_faces (a Gmsh mesh?); allowed with --refine h: a built-in box mesh, or --geo with the mesh's .geo file (or use --refine p)")
        companions = ["coarser", "finer"] if args.companion == "auto" else [args.companion]
        thirds = ["coarser", "finer"] if args.third == "auto" else [args.third]
        tried = []
        for companion in companions:
            for third in (thirds if args.levels == 3 else ["coarser"]):
                levels, misfit = box_levels(options, args, ladder(companion, third, args.levels))
                if levels and not misfit:
                    if tried:
                        print(f"convergence_check: {tried[0]}: the levels are {', '.join(n for n, _, _ in levels)} instead", flush=True)
                    steps = ladder(companion, third, args.levels)
                    return levels, steps.index(0)
                tried.append(misfit)
        fail(tried[0] + ("" if tried[0].startswith("-mesh_box_faces") else ", so the region would change shape with the level; allowed: region box edges on the "
                         "cell edges of every level (another --companion or --third, or another -mesh_box_faces)"))
    degree = int(options.get("element_degree", "1"))
    given = [int(x) for x in (args.degrees or "").split(",") if x.strip()]
    if len(given) != args.levels - 1 or any(d < 1 for d in given):
        fail(f"--degrees {args.degrees or '(not given)'}; allowed with --refine p and --levels {args.levels}: {args.levels - 1} degree(s) >= 1 other than the scene's {degree}, comma-separated")
    degrees = sorted(set([degree] + given), reverse=True)
    if len(degrees) != args.levels:
        fail(f"--degrees {args.degrees}; allowed: degrees that differ from each other and from the scene's {degree}")
    levels = [("main" if d == degree else f"p{d}", ["-element_degree", str(d)], degree / d) for d in degrees]
    return levels, degrees.index(degree)


def region_boxes_misfit(options, level_faces):
    """Why a region box of the scene does not lie on the cell edges of every level (a box
    edge through cells would change the region's shape with the level); None if it does."""
    lower = numbers(options.get("mesh_box_lower", "0,0,0"), "mesh_box_lower")
    upper = numbers(options.get("mesh_box_upper", "1,1,1"), "mesh_box_upper")
    for name, value in options.items():
        if not (name.startswith("region_") and name.endswith("_box")):
            continue
        box = numbers(value, name)
        for level, faces in level_faces:
            for a in range(min(len(faces), len(box) // 2)):
                h = (upper[a] - lower[a]) / faces[a]
                for edge in box[2 * a:2 * a + 2]:
                    cells = (edge - lower[a]) / h
                    inside = lower[a] - 1e-9 * h < edge < upper[a] + 1e-9 * h
                    if inside and abs(cells - round(cells)) > 1e-6:
                        return (f"-{name} {value}: {'xyz'[a]} = {edge:g} lies inside a cell of the {level} level ({h:g} m cells, -mesh_box_faces "
                                f"{','.join(str(int(n)) for n in faces)})")
    return None


def mesh_levels(args, levels):
    """Meshes every level of --geo with Gmsh into its -mesh_file; returns the cell counts
    (Gmsh's elements of the mesh's dimension)."""
    counts = []
    for name, level_options, h in levels:
        target = level_options[1]
        command = ["gmsh", f"-{args.geo_dim}", args.geo, "-clscale", f"{h:.17g}", "-format", "msh41", "-o", target]
        for item in (args.geo_set or "").split(","):
            if item.strip():
                key, _, value = item.partition("=")
                command += ["-setnumber", key.strip(), value.strip()]
        print(f"  {name} mesh: {shlex.join(command)}", flush=True)
        try:
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        except FileNotFoundError:
            fail("--geo needs gmsh on the PATH; allowed: install it (make deps) or a box scene")
        errors = [line for line in done.stdout.splitlines() if line.startswith("Error")]
        if done.returncode != 0 or errors or not os.path.isfile(target):
            fail(f"--geo {args.geo}: gmsh failed for the {name} level ({(errors or done.stdout.strip().splitlines()[-1:] or [''])[0]})")
        counts.append(msh_cell_count(target, args.geo_dim))
    return counts


def msh_cell_count(path, dim):
    """Elements of dimension dim in a Gmsh 4.1 ASCII file."""
    count, lines = 0, open(path).read().split("\n")
    start = lines.index("$Elements")
    blocks = int(lines[start + 1].split()[0])
    i = start + 2
    for _ in range(blocks):
        entity_dim, _, _, n = (int(x) for x in lines[i].split())
        count += n if entity_dim == dim else 0
        i += n + 1
    return count


def launcher():
    mpiexec = shlex.split(os.environ.get("MPIEXEC", "mpiexec"))
    if "MPIEXEC_FLAGS" in os.environ:
        flags = shlex.split(os.environ["MPIEXEC_FLAGS"])
    else:
        flags = ["--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    return mpiexec + flags


def run_level(args, name, level_options, extra):
    folder = os.path.join(args.out, name)
    log = os.path.join(args.out, f"{name}.log")
    stamp = os.path.join(args.out, f"{name}.command")
    binary = os.environ.get("SLIPWAVE", os.path.join(ROOT, "build", "slipwave"))
    command = launcher() + ["-n", str(args.np), binary, "-options_file", args.scene] + extra + level_options + ["-output_dir", folder, "-output_overwrite"]
    text = shlex.join(command)
    if args.reuse and os.path.exists(stamp) and open(stamp).read().strip() == text and os.path.exists(os.path.join(folder, "run_info.json")):
        print(f"  {name}: reused {folder}", flush=True)
        return folder, command
    if os.path.exists(stamp):
        os.remove(stamp)
    print(f"  {name}: {text}", flush=True)
    with open(log, "w") as out:
        if args.echo_main and name == "main":
            # The run's own report and progress as it runs (make run), and the log as usual.
            with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True) as run:
                for line in run.stdout:
                    out.write(line)
                    sys.stdout.write(line)
                    sys.stdout.flush()
            rc = run.returncode
        else:
            rc = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT)
    if rc != 0:
        tail = open(log).read().strip().splitlines()[-1:] or [""]
        fail(f"the {name} run exited {rc} ({log}: {tail[0]})")
    with open(stamp, "w") as f:
        f.write(text + "\n")
    return folder, command


# ---------------------------------------------------------------- the report


def banded(key):
    return key not in NOT_BANDED and not key.startswith(NOT_BANDED_PREFIXES)


def report(answers, levels, main, order, ratios):
    """{key: grid_band(...)} for every answer found on every level."""
    keys = [k for k in answers[main] if banded(k) and all(k in a for a in answers)]
    return {k: grid_band([a[k] for a in answers], ratios, order, main) for k in keys}


def table(bands, units):
    lines = [f"{'answer':40s} {'value':>12s} {'band +-':>11s} {'band':>7s} {'order':>12s}  unit; note (order: observed, or observed>used, or assumed)"]
    for key, b in bands.items():
        rel = "" if b["relative_band"] is None else f"{100 * b['relative_band']:6.1f}%"
        if b["order_observed"] is None:
            order = f"{b['order']:g} assumed"
        elif b["order_observed"] > b["order"]:
            order = f"{b['order_observed']:.2f}>{b['order']:g}"
        else:
            order = f"{b['order_observed']:.2f} obs"
        lines.append(f"{key:40s} {b['value']:12.5g} {b['band']:11.3g} {rel:>7s} {order:>12s}  {units(key)}{'; ' + b['note'] if b['note'] else ''}")
    return "\n".join(lines)


# The bound an answer's band must keep to be read as converged (issue 21's 5 %).
CONVERGED_BAND = 0.05


def summary(bands):
    """Two lines that sort the answers by their band: within CONVERGED_BAND of the value, and
    wider (each with its band), so the reader sees which numbers the mesh has settled."""
    tight = [k for k, b in bands.items() if b["relative_band"] is not None and b["relative_band"] <= CONVERGED_BAND]
    wide = [f"{k} (+-{100 * b['relative_band']:.0f} %)" for k, b in bands.items() if b["relative_band"] is not None and b["relative_band"] > CONVERGED_BAND]
    zero = [k for k, b in bands.items() if b["relative_band"] is None]
    lines = [f"answers with a band within {100 * CONVERGED_BAND:g} %: {', '.join(tight) or 'none'}",
             f"answers with a wider band (read them with it): {', '.join(wide) or 'none'}"]
    if zero:
        lines.append(f"zero on the main level (no relative band): {', '.join(zero)}")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description="Runs a scene at its resolution and a companion, and reports each main answer with a grid-convergence band.",
                                     usage="%(prog)s SCENE --out DIR [options] [-- SLIPWAVE OPTIONS...]")
    parser.add_argument("scene", metavar="SCENE")
    parser.add_argument("--out", required=True, metavar="DIR", help="output folder; the runs go into its subfolders")
    parser.add_argument("--np", type=int, default=2, help="MPI ranks of each run (default 2)")
    parser.add_argument("--levels", type=int, default=2, help="2 (main and companion) or 3")
    parser.add_argument("--refine", default="h", help="h: -mesh_box_faces (default); p: -element_degree")
    parser.add_argument("--companion", default="auto", help="coarser, finer, or auto (default): coarser where the scene's region boxes fit it")
    parser.add_argument("--third", default="auto", help="with --levels 3: coarser, finer or auto (default), one step beyond the other two")
    parser.add_argument("--degrees", help="with --refine p: the other levels' degrees, e.g. 1 or 2,1")
    parser.add_argument("--axes", help="with --refine h: the axes to refine, e.g. y (default all)")
    parser.add_argument("--geo", help="with --refine h: the Gmsh .geo the levels are meshed from (-clscale 2^-k)")
    parser.add_argument("--geo-set", help="with --geo: the file's numbers, NAME=VALUE,... (gmsh -setnumber)")
    parser.add_argument("--geo-dim", type=int, default=2, help="with --geo: the mesh's dimension, 2 (default) or 3")
    parser.add_argument("--order", type=float, default=1.0, help="formal order where none is observed (default 1)")
    parser.add_argument("--interface", default="base")
    parser.add_argument("--echo-main", action="store_true", help="print the main run's output as it runs (it also goes to its log)")
    parser.add_argument("--reuse", action="store_true", help="keep a level whose folder holds a run of the same command")
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    args = parser.parse_args(argv)
    for name, value, allowed in (("--levels", args.levels, (2, 3)), ("--refine", args.refine, ("h", "p")),
                                 ("--companion", args.companion, ("auto", "coarser", "finer")), ("--third", args.third, ("auto", "coarser", "finer"))):
        if value not in allowed:
            fail(f"{name} {value}; allowed: {' or '.join(str(a) for a in allowed)}")
    if args.np < 1:
        fail(f"--np {args.np}; allowed: 1 or more ranks")
    if args.geo is not None and (args.refine != "h" or not os.path.isfile(args.geo)):
        fail(f"--geo {args.geo}: " + ("no such file; allowed: a Gmsh .geo file" if args.refine == "h" else f"with --refine {args.refine}; allowed: --refine h"))
    if args.geo_dim not in (2, 3):
        fail(f"--geo-dim {args.geo_dim}; allowed: 2 or 3")
    if not args.order > 0:
        fail(f"--order {args.order:g}; allowed: a formal order > 0")
    if not os.path.isfile(args.scene):
        fail(f"SCENE {args.scene}: no such file; allowed: a slipwave options file")
    options = read_options_file(args.scene)
    if args.refine == "h" and args.geo is None and "mesh_file" in options and "mesh_box_faces" not in options:
        # a scene whose Gmsh mesh lies beside its .geo (config/scenes/default.msh, default.geo):
        # the levels come from that file, as with --geo
        geo = os.path.splitext(os.path.join(os.path.dirname(os.path.abspath(args.scene)), options["mesh_file"]))[0] + ".geo"
        if os.path.isfile(geo):
            args.geo = os.path.relpath(geo)
            print(f"convergence_check: the levels are meshed from {args.geo}, the .geo beside the scene's mesh_file {options['mesh_file']} (as --geo)", flush=True)
    options.update(command_line_options(extra))
    levels, main_index = levels_of(options, args)
    refined = ("mesh_file",) if args.geo else ("mesh_box_faces",) if args.refine == "h" else ("element_degree",)
    extra = without_options(extra, refined + ("output_dir", "output_overwrite"))
    ratios = [levels[i + 1][2] / levels[i][2] for i in range(len(levels) - 1)]
    os.makedirs(args.out, exist_ok=True)
    print(f"convergence_check: {args.scene}, {len(levels)} levels ({', '.join(n for n, _, _ in levels)}), {args.np} rank(s) each", flush=True)
    if args.geo:
        counts = mesh_levels(args, levels)
        print("  cells: " + ", ".join(f"{name} {n}" for (name, _, _), n in zip(levels, counts)) + " (r = 2, the size factor's ratio; the counts' ratios "
              + ", ".join(f"{counts[i] / counts[i + 1]:.3g}" for i in range(len(counts) - 1)) + f": {2 ** args.geo_dim} where the sizes halve in every direction)", flush=True)
    runs = [run_level(args, name, level_options, extra) for name, level_options, _ in levels]
    from slipwave import RunFolder  # scene_metrics put python/ on the path
    f_cut = min(scene_metrics.resolved_frequency(RunFolder(folder)) for folder, _ in runs)
    answers = []
    for folder, _ in runs:
        notes = []
        answers.append(scene_metrics.metrics(folder, args.interface, f_cut, notes))
    bands = report(answers, levels, main_index, args.order, ratios)
    main_folder = runs[main_index][0]
    result = {
        "scene": args.scene,
        "method": "Roache's grid convergence index: Fs = 1.25 with three levels and the observed order, Fs = 3 with the formal order otherwise (scripts/convergence_check.py)",
        "refine": args.refine, "formal_order": args.order, "ratios": ratios, "main_level": levels[main_index][0],
        "lowpass_frequency_hz": f_cut,
        "levels": [{"name": name, "options": level_options, "folder": os.path.relpath(folder, args.out), "command": command, "answers": a}
                   for (name, level_options, _), (folder, command), a in zip(levels, runs, answers)],
        "answers": {k: dict(b, unit=scene_metrics.unit(k)) for k, b in bands.items()},
    }
    with open(os.path.join(main_folder, "convergence.json"), "w") as f:
        json.dump(result, f, indent=1)
    info_path = os.path.join(main_folder, "run_info.json")
    info = json.load(open(info_path))
    info["convergence"] = result
    with open(info_path, "w") as f:
        json.dump(info, f, indent=1)
    print(f"\nAnswers of the main run ({main_folder}) with their grid-convergence band "
          f"(low-passed peaks at {f_cut:.3g} Hz, the coarsest level's resolved frequency):")
    print(table(bands, scene_metrics.unit))
    print(summary(bands))
    print(f"\nwritten: {os.path.join(main_folder, 'convergence.json')}, and the key \"convergence\" of {info_path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
