"""Opens a slipwave run folder in ParaView with the views that show what happened, and saves a
PNG screenshot (off-screen); optionally a state file to open in the ParaView window.

usage: xvfb-run -a pvpython --force-offscreen-rendering scripts/paraview_views.py OUT
           [--png FILE] [--state FILE.pvsm] [--time T] [--color FIELD] [--scale S]

  volume.xmf           warped by displacement_relative (the displacement less the base's mean
                       one: deformation and rocking, not the ground's drift) times the scale,
                       coloured by --color (default: the magnitude of displacement_relative;
                       any node or cell field of the volume: velocity, stress, ...)
  interface_<n>.xmf    each interface's grid, warped the same way by its soil side's
                       displacement_relative, drawn as thick lines (2D) or a surface (3D)
                       coloured by the pairs' status (0 stick, 1 slip, 2 open)
--time: the frame at or before T [s] (default the last); --scale: the warp factor (default: the
largest relative displacement of that frame drawn as 3 % of the model's size; the title says
which). --png defaults to OUT/plots/view.png. Debian's ParaView needs an X server even off
screen: run it under xvfb-run (package xvfb). In the ParaView window: View > Python Shell >
Run Script, with OUT in sys.argv, or load the --state file.
"""
import argparse
import glob
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction,
                             GetScalarBar, SaveScreenshot, SaveState, Show, Text, UpdatePipeline,
                             WarpByVector, Xdmf3ReaderS)

WARP_FIELD = "displacement_relative"
WARP_SHARE = 0.02  # the largest relative displacement drawn as this share of the model's size


def fail(message):
    print(f"paraview_views: error: {message}", file=sys.stderr)
    sys.exit(1)


def frame_time(reader, wanted):
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    if wanted is None:
        return times[-1]
    before = [t for t in times if t <= wanted * (1 + 1e-12)]
    if not before:
        fail(f"--time {wanted}: allowed: a time from {times[0]} to {times[-1]} s")
    return before[-1]


def largest(data, field):
    """The largest magnitude of a node field of the reader's output at the current time."""
    array = data.GetPointData().GetArray(field)
    return array.GetRange(-1)[1] if array is not None else 0.0


def main():
    parser = argparse.ArgumentParser(description="ParaView views of a slipwave run folder.")
    parser.add_argument("out", metavar="OUT")
    parser.add_argument("--png", help="screenshot file (default OUT/plots/view.png)")
    parser.add_argument("--state", help="also save a ParaView state file (.pvsm)")
    parser.add_argument("--time", type=float, help="the frame's time [s] (default the last)")
    parser.add_argument("--color", default=WARP_FIELD, help=f"the volume's colour field (default {WARP_FIELD})")
    parser.add_argument("--scale", type=float, help="warp factor (default: the largest relative displacement "
                                                    f"as {100 * WARP_SHARE:g} %% of the model's size)")
    args = parser.parse_args()
    volume_xmf = os.path.join(args.out, "volume.xmf")
    if not os.path.isfile(volume_xmf):
        fail(f"{volume_xmf} is missing; allowed: the -output_dir of a run with volume output (-output_fields true)")
    png = args.png or os.path.join(args.out, "plots", "view.png")
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)

    view = GetActiveViewOrCreate("RenderView")
    volume = Xdmf3ReaderS(registrationName="volume", FileName=[volume_xmf])
    volume.UpdatePipelineInformation()
    t = frame_time(volume, args.time)
    GetAnimationScene().AnimationTime = t
    view.ViewTime = t
    UpdatePipeline(time=t, proxy=volume)
    data = servermanager.Fetch(volume)
    fields = [data.GetPointData().GetArrayName(i) for i in range(data.GetPointData().GetNumberOfArrays())]
    cells = [data.GetCellData().GetArrayName(i) for i in range(data.GetCellData().GetNumberOfArrays())]
    if WARP_FIELD not in fields:
        fail(f"{volume_xmf} has no node field {WARP_FIELD} (written by slipwave since the relative displacement was added)")
    if args.color not in fields + cells:
        fail(f"--color {args.color}: allowed: {', '.join(fields + cells)}")
    bounds = data.GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    peak = largest(data, WARP_FIELD)
    scale = args.scale if args.scale is not None else (WARP_SHARE * size / peak if peak > 0 else 1.0)

    warped = WarpByVector(registrationName="volume warped", Input=volume, Vectors=["POINTS", WARP_FIELD], ScaleFactor=scale)
    shown = Show(warped, view)
    ColorBy(shown, ("CELLS" if args.color in cells and args.color not in fields else "POINTS", args.color, "Magnitude"))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    colors = GetColorTransferFunction(args.color)
    colors.ApplyPreset("Viridis (matplotlib)", True)
    bar = GetScalarBar(colors, view)
    bar.Title, bar.ComponentTitle = args.color + (" [m]" if args.color.startswith("displacement") else ""), "magnitude"
    bar.WindowLocation = "Any Location"
    bar.Position, bar.ScalarBarLength = [0.90, 0.30], 0.4

    dim3 = bounds[5] - bounds[4] > 0
    for xmf in sorted(glob.glob(os.path.join(args.out, "interface_*.xmf"))):
        name = os.path.basename(xmf)[len("interface_"):-len(".xmf")]
        grid = Xdmf3ReaderS(registrationName=f"interface {name}", FileName=[xmf])
        UpdatePipeline(time=t, proxy=grid)
        iface = WarpByVector(registrationName=f"interface {name} warped", Input=grid, Vectors=["POINTS", WARP_FIELD],
                             ScaleFactor=scale)
        line = Show(iface, view)
        ColorBy(line, ("POINTS", "status"))
        status = GetColorTransferFunction("status")
        status.ApplyPreset("Rainbow Uniform", True)
        status.RescaleTransferFunction(0.0, 2.0)
        line.LineWidth = 5.0
        line.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(status, view)
        bar.Title, bar.ComponentTitle = "interface status", "0 stick 1 slip 2 open"
        bar.WindowLocation = "Any Location"
        bar.Orientation = "Horizontal"
        bar.Position, bar.ScalarBarLength = [0.05, 0.05], 0.3
        if not dim3:
            line.SetRepresentationType("Wireframe")

    title = Text(registrationName="title")
    title.Text = (f"{os.path.abspath(args.out)}   t = {t:.3f} s\n"
                  f"warped by {WARP_FIELD} (displacement less the base's) x {scale:.3g}, largest {peak:.3g} m;"
                  f" colour: {args.color}")
    title_display = Show(title, view)
    title_display.FontSize = 16
    title_display.WindowLocation = "Upper Center"

    view.OrientationAxesVisibility = 1
    if dim3:
        view.CameraPosition = [1, -1.5, 1]
        view.CameraViewUp = [0, 0, 1]
    else:
        view.InteractionMode = "2D"
        view.CameraPosition = [0, 0, 1]
        view.CameraViewUp = [0, 1, 0]
    view.CameraFocalPoint = [0, 0, 0]
    view.ResetCamera(False)
    view.ViewSize = [1600, 900]
    SaveScreenshot(png, view, ImageResolution=[1600, 900], FontScaling="Do not scale fonts")
    print(f"paraview_views: {png} (t = {t:.6g} s, warp x {scale:.4g})")
    if args.state:
        SaveState(args.state)
        print(f"paraview_views: {args.state}")


if __name__ == "__main__":
    main()
