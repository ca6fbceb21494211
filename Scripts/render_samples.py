"""Render the bundled LAMMPS samples with the Particles representation (pvpython).

usage: pvpython render_samples.py --plugin ParticleRendering.so --data Testing/Data --out DIR
Writes DIR/<scene>.png for every sample found and prints the paths.
"""
import argparse
import os
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, LoadPlugin, Render,
                             SaveScreenshot, Show, XMLPolyDataReader, Delete)

SCENES = [
    # file, colour array, direction from the focal point to the camera, zoom, translucent
    ("lj_droplets.vtp", "type", (1.0, -1.6, 0.9), 2.2, False),
    ("lj_droplets.vtp", "type", (1.0, -1.6, 0.9), 2.2, True),
    ("lj_film.vtp", "speed", (1.0, -1.8, 0.6), 1.4, False),
    ("fcc_block.vtp", "type", (1.2, -1.5, 1.0), 1.1, False),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="1200x900")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    LoadPlugin(args.plugin, remote=False, ns=globals())
    os.makedirs(args.out, exist_ok=True)
    written = []
    for name, color, direction, zoom, translucent in SCENES:
        path = os.path.join(args.data, name)
        if not os.path.exists(path):
            print("missing sample %s, skipped" % path, file=sys.stderr)
            continue
        reader = XMLPolyDataReader(FileName=[path])
        view = CreateView("RenderView")
        view.ViewSize = [width, height]
        view.OrientationAxesVisibility = 0
        view.Background = [0.12, 0.12, 0.16]
        try:
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        display = Show(reader, view)
        display.Representation = "Particles"
        display.UseRadiusArray = 1
        display.RadiusArray = ["POINTS", "radius"]
        display.Specular = 0.3
        if translucent:
            # emission-absorption glyphs: slow (liquid) atoms nearly clear, vapour opaque
            display.UseOpacityArray = 1
            display.ParticleOpacityArray = ["POINTS", "speed"]
            display.OpacityArrayRangeMode = "Custom"
            display.OpacityArrayRange = [0.0, 3.0]
            display.DensityModel = "Squared Distance"
            display.HollowFraction = 0.4
        ColorBy(display, ("POINTS", color))
        lut = GetColorTransferFunction(color)
        lut.ApplyPreset("Jet" if color == "speed" else "Cool to Warm", True)
        display.RescaleTransferFunctionToDataRange(True, False)
        Render(view)  # the first render resets the camera: place it afterwards
        view.ResetCamera()
        camera = view.GetActiveCamera()
        focal = camera.GetFocalPoint()
        distance = camera.GetDistance()
        norm = sum(d * d for d in direction) ** 0.5
        camera.SetPosition(*[f + 1.2 * distance * d / norm for f, d in zip(focal, direction)])
        camera.SetViewUp(0, 0, 1)
        view.ResetCamera()
        camera.Zoom(zoom)
        Render(view)
        png = os.path.join(args.out, os.path.splitext(name)[0] +
                           ("_translucent" if translucent else "") + ".png")
        SaveScreenshot(png, view, ImageResolution=[width, height])
        written.append(png)
        Delete(view)
        del view
    print("Rendered %d sample image(s):" % len(written))
    for png in written:
        print("  " + os.path.abspath(png))
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main())
