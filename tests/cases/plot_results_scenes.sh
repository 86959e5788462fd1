# Plots of every shipped scene (config/scenes/*.yaml), each run for a few hundredths of a
# second (sliding_block with the 0.4 g pulse its header describes), checked from the matplotlib
# figure objects (plot_results.save is wrapped to look at each figure before it is written):
# every axis that plots data has x and y labels with a unit in brackets; accelerations are in
# g; spectra have a log period axis and N_PERIODS = 200 periods from 0.02 to 5 s with the band
# T < 1 / resolved_frequency_hz (run_info.json) shaded where it is above 0.02 s; the figures use constrained layout (the
# suptitle does not overlap the first row); no energy label claims the old "external work
# (gravity, tractions, supports)". Default scene: the station rows are the input motion, then
# the stations by their coordinates (default.yaml) from the highest: block_top (y 40), the base
# corners (30.25), block_base (30, x 0), free_field (30, x 40), bedrock (-20); the amplification
# figure marks 4 H / vs = 4 x 30 / 200 = 0.6 s (--layer 30,200), and the interface history
# has a rocking-angle panel.
set -eu
. tests/tools/lib.sh
printf 't,a\n0,3.92266\n0.2,3.92266\n0.2001,0\n1,0\n' > "$WORK/pulse.csv"
# The scenes' runs are independent: two at a time (tests/tools/together.sh); so are the
# scenes' figures: two worker processes (multiprocessing), each scene's checks in its worker.
. tests/tools/together.sh
for scene in config/scenes/*.yaml; do
  name=$(basename "$scene" .yaml)
  extra="-ts_max_time 0.04 -output_interval 0.01"
  case $name in
    two_bar_impact) extra="-ts_max_time 0.004 -output_interval 0.001" ;;
    sliding_block) extra="$extra -bc_bottom_record $WORK/pulse.csv" ;;
  esac
  together $SW -options_file "$scene" $extra -progress_interval 1000 -output_dir "$WORK/$name" > "$WORK/$name.log"
done
together_wait
cat > "$WORK/check_plots.py" <<'PY'
import multiprocessing
import os, sys
sys.path.insert(0, "scripts")
import numpy as np
import plot_results as pr
w = sys.argv[1]
seen = {}
original = pr.save
def inspect(fig, path, written):
    name = os.path.basename(path)
    assert fig.get_layout_engine() is not None and "Constrained" in type(fig.get_layout_engine()).__name__, (path, "layout")
    for ax in fig.axes:
        if ax.get_label() == "<colorbar>" or ax.name == "3d" or not (ax.lines or ax.collections):
            continue
        # An axis sharing x with others may leave the label to the bottom one.
        xlabel = ax.get_xlabel() or next((a.get_xlabel() for a in ax.get_shared_x_axes().get_siblings(ax) if a.get_xlabel()), "")
        for label in (xlabel, ax.get_ylabel()):
            assert "[" in label and "]" in label, f"{path}: axis label {label!r} has no unit"
        if "acceleration" in name:
            assert ax.get_ylabel() == "acceleration [g]", (path, ax.get_ylabel())
        if name in ("spectra.png", "amplification.png", "transfer_ratio.png"):
            assert ax.get_xscale() == "log", (path, ax.get_xscale())
            for line in ax.lines:
                x = line.get_xdata()
                if len(x) > 2:
                    assert len(x) == 200 and abs(x[0] - 0.02) < 1e-12 and abs(x[-1] - 5) < 1e-12, (path, len(x))
    for ax in fig.axes:
        for text in [ax.get_title()] + [t.get_text() for t in (ax.get_legend().get_texts() if ax.get_legend() else [])]:
            assert "tractions, supports" not in text and "includes gravity" not in text, (path, text)
    seen.setdefault(os.path.basename(os.path.dirname(os.path.dirname(path))), {})[name] = fig
    original(fig, path, written)
pr.save = inspect


def check_scene(scene):
    """One scene's figures and checks (in a worker process; an AssertionError fails the test)."""
    out = os.path.join(w, scene)
    written = pr.make_figures(out, os.path.join(out, "plots"), layer=(30, 200) if scene == "default" else None)
    assert written, f"{scene}: nothing plotted"
    info = pr.run_info(pr.RunFolder(out))
    for fig_name, fig in seen.get(scene, {}).items():
        if fig_name in ("spectra.png", "amplification.png") and 1 / info.get("resolved_frequency_hz", 1e9) > 0.02:
            spans = [p for p in fig.axes[0].patches]
            edge = 1 / info["resolved_frequency_hz"]
            assert any(abs(p.get_xy()[:, 0].max() - edge) < 1e-9 for p in spans), f"{scene} {fig_name}: no band up to {edge} s"
    lines = [f"ok - {scene}: {', '.join(sorted(seen.get(scene, {})))}"]
    if scene == "default":
        d = seen["default"]
        titles = [ax.get_title() for ax in d["stations_acceleration.png"].axes[::2]]
        expected = ["input (outcrop motion)", "'block_top'", "'block_base_left'", "'block_base_right'", "'block_base'", "'free_field'", "'bedrock'"]
        assert all(t.startswith(e) for t, e in zip(titles, expected)) and len(titles) == len(expected), titles
        legend = [t.get_text() for t in d["amplification.png"].axes[0].get_legend().get_texts()]
        assert any("= 0.6 s" in t for t in legend), legend
        assert "input (outcrop motion)" in [l.get_label() for l in d["spectra.png"].axes[0].lines]
        assert any(ax.get_ylabel() == "rocking angle [mrad]" for ax in d["interface_base_history.png"].axes)
        assert any("dissipated by interface slip" in l.get_label() for ax in d["energy.png"].axes for l in ax.lines)
        lines.append("ok - default: station order, layer period, input spectrum, rocking panel, slip energy")
    return lines


scenes = sorted(s for s in os.listdir(w) if os.path.isdir(os.path.join(w, s)))
assert "default" in scenes, scenes
with multiprocessing.get_context("fork").Pool(2) as pool:
    for lines in pool.imap(check_scene, scenes):
        print("\n".join(lines))
print("plot_results_scenes: OK")
PY
$PY "$WORK/check_plots.py" "$WORK"
