"""vtkMMPLDReader against MMPLD files written here, byte by byte from MegaMol's specification
(SpecMMPLD 1.3 and MegaMol's MMPLDDataSource/MMPLDWriter: 60-byte header "MMPLD\\0", uint16
version, uint32 frame count, bounding and clipping box, frames+1 uint64 offsets; per frame an
optional float timestamp (>= 1.2) and a uint32 list count; per list uint8 vertex and colour type,
a global radius (vertex types 1, 3, 4), a global RGBA colour (colour type 0) or an intensity range
(3, 7), a uint64 count, a list box (>= 1.3), the interleaved particles, and cluster information
(1.1)). No MegaMol file is available here, so this writer is the format's independent statement.

Checked: versions 1.0, 1.1 (with cluster info), 1.2 and 1.3; every vertex type (float xyz, float
xyzr, uint16 xyz, double xyz, none) and colour type (none with a global colour, uint8 RGB/RGBA,
float intensity, float RGB/RGBA, uint16 RGBA, double intensity); several lists per frame; frames
as time steps (timestamps, or the frame index); a 1.3 frame without a timestamp (as MegaMol wrote
them in 2018-2019). Bad input: version 0 (an unfinished file), frame count 0, a truncated last
frame (the frames before it read), a decreasing frame table, an unknown vertex type, a list count
larger than its frame, not an MMPLD file -- each with a clear message and no crash.

usage: python3 TestMMPLDReader.py --temp DIR
"""
import argparse
import os
import random
import struct
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particlerendering as pr
import prVTKTesting  # noqa: E402
from prVTKTesting import check, finish  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

VERTEX = {1: "<3f", 2: "<4f", 3: "<3H", 4: "<3d", 0: ""}
COLOUR = {0: "", 1: "<3B", 2: "<4B", 3: "<f", 4: "<3f", 5: "<4f", 6: "<4H", 7: "<d"}




def make_list(vertex, colour, count, rng):
    """A particle list: its header values and particles (positions, radius, colour values)."""
    lst = {"vertex": vertex, "colour": colour, "radius": 0.25, "global": (10, 20, 30, 200),
           "range": (0.5, 2.5), "count": count if vertex else 0, "particles": []}
    for _ in range(lst["count"]):
        if vertex == 3:
            x = [rng.randrange(0, 65536) for _ in range(3)]
        else:
            x = [rng.uniform(-5, 5) for _ in range(3)]
        r = rng.uniform(0.1, 0.9)
        if colour in (1, 2):
            c = [rng.randrange(256) for _ in range(3 if colour == 1 else 4)]
        elif colour in (4, 5):
            c = [rng.uniform(-0.1, 1.1) for _ in range(3 if colour == 4 else 4)]
        elif colour == 6:
            c = [rng.randrange(65536) for _ in range(4)]
        elif colour in (3, 7):
            c = [rng.uniform(0.0, 3.0)]
        else:
            c = []
        lst["particles"].append((x, r, c))
    return lst


def list_bytes(lst, version):
    out = struct.pack("<BB", lst["vertex"], lst["colour"])
    if lst["vertex"] in (1, 3, 4):
        out += struct.pack("<f", lst["radius"])
    if lst["colour"] == 0:
        out += struct.pack("<4B", *lst["global"])
    elif lst["colour"] in (3, 7):
        out += struct.pack("<2f", *lst["range"])
    out += struct.pack("<Q", lst["count"])
    if version >= 103:
        out += struct.pack("<6f", -5, -5, -5, 5, 5, 5)
    for x, r, c in lst["particles"]:
        if lst["vertex"] == 2:
            out += struct.pack("<4f", x[0], x[1], x[2], r)
        else:
            out += struct.pack(VERTEX[lst["vertex"]], *x)
        if COLOUR[lst["colour"]]:
            out += struct.pack(COLOUR[lst["colour"]], *c)
    if version == 101:
        out += struct.pack("<IQ", 3, 8) + b"\x01\x02\x03\x04\x05\x06\x07\x08"  # cluster info
    return out


def write_mmpld(path, version, frames, times=None, timestamp=True, frame_count=None,
                truncate=0, table=None):
    body = []
    for f, lists in enumerate(frames):
        data = b""
        if version >= 102 and timestamp:
            data += struct.pack("<f", times[f] if times else 0.0)
        data += struct.pack("<I", len(lists))
        for lst in lists:
            data += list_bytes(lst, version)
        body.append(data)
    n = len(frames) if frame_count is None else frame_count
    offsets = [60 + 8 * (len(frames) + 1)]
    for data in body:
        offsets.append(offsets[-1] + len(data))
    if table:
        offsets = table(offsets)
    header = b"MMPLD\0" + struct.pack("<HI", version, n) + struct.pack("<6f", -5, -5, -5, 5, 5, 5) + \
        struct.pack("<6f", -6, -6, -6, 6, 6, 6) + struct.pack("<%dQ" % len(offsets), *offsets)
    content = header + b"".join(body)
    with open(path, "wb") as f:
        f.write(content[: len(content) - truncate])


def open_reader(path):
    return prVTKTesting.open_reader(pr.vtkMMPLDReader(), path)


def expected_arrays(lists):
    """What the reader should produce for the lists of one frame."""
    pos, radius, colour, intensity, index = [], [], [], [], []
    any_colour = any(l["colour"] not in (3, 7) for l in lists)
    any_intensity = any(l["colour"] in (3, 7) for l in lists)
    for li, l in enumerate(lists):
        for x, r, c in l["particles"]:
            # as written: float32 for float vertex types, exact for uint16 and double
            pos.append([float(numpy.float32(v)) for v in x] if l["vertex"] in (1, 2) else x)
            radius.append(r if l["vertex"] == 2 else l["radius"])
            index.append(li)
            k = l["colour"]
            if k == 0:
                rgba = list(l["global"])
            elif k == 1:
                rgba = c + [255]
            elif k == 2:
                rgba = c
            elif k in (4, 5):
                f = c + ([1.0] if k == 4 else [])
                rgba = [int(round(255 * min(1.0, max(0.0, numpy.float32(v))))) for v in f]
            elif k == 6:
                rgba = [(v + 128) // 257 for v in c]
            else:
                rgba = [192, 192, 192, 255]
            colour.append(rgba)
            intensity.append(numpy.float32(c[0]) if k in (3, 7) else numpy.nan)
    return (numpy.array(pos), numpy.array(radius, dtype=numpy.float32),
            numpy.array(colour, dtype=numpy.uint8) if any_colour else None,
            numpy.array(intensity, dtype=numpy.float32) if any_intensity else None,
            numpy.array(index))


def compare(reader, time, lists, label):
    reader.UpdateTimeStep(time)
    out = reader.GetOutput()
    pos, radius, colour, intensity, index = expected_arrays(lists)
    n = len(index)
    got = vtk_to_numpy(out.GetPoints().GetData()) if n else numpy.zeros((0, 3))
    exact = numpy.array(pos, dtype=numpy.float64)
    check(out.GetNumberOfPoints() == n and out.GetNumberOfVerts() == n, "%s: %d points, expected %d"
          % (label, out.GetNumberOfPoints(), n))
    if not n:
        return
    # uint16 positions are exact; float positions as float; double positions exact
    ok = numpy.array_equal(got.astype(numpy.float64), exact.astype(numpy.float64)) if n else True
    check(ok, "%s: points" % label)
    pd = out.GetPointData()
    check(numpy.array_equal(vtk_to_numpy(pd.GetArray("radius")), radius), "%s: radius" % label)
    check(numpy.array_equal(vtk_to_numpy(pd.GetArray("list")), index), "%s: list index" % label)
    if colour is not None:
        check(numpy.array_equal(vtk_to_numpy(pd.GetArray("color")), colour), "%s: colour" % label)
    else:
        check(pd.GetArray("color") is None, "%s: no colour array" % label)
    if intensity is not None:
        got_i = vtk_to_numpy(pd.GetArray("intensity"))
        check(numpy.array_equal(numpy.isnan(got_i), numpy.isnan(intensity)) and
              numpy.array_equal(got_i[~numpy.isnan(got_i)], intensity[~numpy.isnan(intensity)]),
              "%s: intensity" % label)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    temp = os.path.join(args.temp, "TestMMPLDReader")
    os.makedirs(temp, exist_ok=True)
    vtkOutputWindow.SetInstance(vtkStringOutputWindow())  # the pipeline's own failure messages
    rng = random.Random(42)

    # every version, every vertex and colour type, several lists per frame
    combos = [(v, c) for v in (1, 2, 3, 4) for c in range(8)] + [(0, 0)]
    for version in (100, 101, 102, 103):
        allowed = [(v, c) for v, c in combos if version == 103 or (v <= 3 and c <= 5)]
        frames = []
        for f in range(3):
            chosen = rng.sample(allowed, 4) if f else allowed  # frame 0 has every combination
            frames.append([make_list(v, c, rng.randrange(0, 6) + (f == 0), rng) for v, c in chosen])
        times = [0.5, 1.25, 4.0]
        path = os.path.join(temp, "v%d.mmpld" % version)
        write_mmpld(path, version, frames, times)
        reader, messages, got_times = open_reader(path)
        expected_times = times if version >= 102 else [0.0, 1.0, 2.0]
        check(reader.GetVersion() == version and got_times == expected_times and not messages.text,
              "v%d: version %d, times %s, messages %s" % (version, reader.GetVersion(), got_times,
                                                          messages.text))
        for f, lists in enumerate(frames):
            compare(reader, expected_times[f], lists, "v%d frame %d" % (version, f))
        print("version %d: %d lists in frame 0, %d particles" % (
            version, len(frames[0]), sum(l["count"] for l in frames[0])))
    check(pr.vtkMMPLDReader.CanReadFile(os.path.join(temp, "v103.mmpld")) == 1, "CanReadFile")

    # a 1.3 file whose frames have no timestamp (MegaMol 2018-2019)
    frames = [[make_list(2, 2, 5, rng)], [make_list(1, 0, 3, rng), make_list(4, 7, 4, rng)]]
    path = os.path.join(temp, "v103_no_time.mmpld")
    write_mmpld(path, 103, frames, timestamp=False)
    reader, messages, times = open_reader(path)
    check(times == [0.0, 1.0] and not messages.text, "v103 without timestamps: %s %s"
          % (times, messages.text))
    for f, lists in enumerate(frames):
        compare(reader, float(f), lists, "v103 without timestamps, frame %d" % f)

    # bad and incomplete files
    def bad(name, what, expect_frames, **kw):
        path = os.path.join(temp, name)
        frames = [[make_list(2, 2, 4, rng)], [make_list(1, 1, 4, rng)], [make_list(1, 1, 4, rng)]]
        write_mmpld(path, kw.pop("version", 102), frames, [0.0, 1.0, 2.0], **kw)
        reader, messages, times = open_reader(path)
        text = " ".join(messages.text)
        check(len(times) == expect_frames and what in text and name in text,
              "%s: %d frames, messages %r (expected %d frames, %r)" % (name, len(times), text,
                                                                       expect_frames, what))
        if expect_frames:
            compare(reader, times[0], frames[0], name + " frame 0")
    bad("unfinished.mmpld", "did not finish writing", 0, version=0)
    bad("noframes.mmpld", "no frames (frame count 0)", 0, frame_count=0)
    bad("truncated.mmpld", "frame 2", 2, truncate=20)
    bad("table.mmpld", "bad frame table entries", 1,
        table=lambda t: t[:2] + [t[1] - 4] + t[3:])
    path = os.path.join(temp, "unknown.mmpld")
    frames = [[make_list(1, 1, 3, rng)], [make_list(1, 1, 3, rng)]]
    write_mmpld(path, 102, frames, [0.0, 1.0])
    data = bytearray(open(path, "rb").read())
    frame1 = struct.unpack("<3Q", bytes(data[60:84]))[1]
    data[frame1 + 8] = 9  # the vertex type of frame 1's list
    open(path, "wb").write(bytes(data))
    reader, messages, times = open_reader(path)
    check(times == [0.0] and "unknown vertex type 9" in " ".join(messages.text),
          "unknown vertex type: %s %s" % (times, messages.text))
    data[frame1 + 8] = 1
    data[frame1 + 10: frame1 + 18] = struct.pack("<Q", 1 << 40)  # count of frame 1's list
    open(path, "wb").write(bytes(data))
    reader, messages, times = open_reader(path)
    check(times == [0.0] and "more than its frame holds" in " ".join(messages.text),
          "huge count: %s %s" % (times, messages.text))
    path = os.path.join(temp, "text.mmpld")
    open(path, "w").write("not a particle file\n")
    reader, messages, times = open_reader(path)
    check(times == [] and "not an MMPLD file" in " ".join(messages.text) and
          pr.vtkMMPLDReader.CanReadFile(path) == 0, "not MMPLD: %s" % messages.text)

    return finish()


if __name__ == "__main__":
    sys.exit(main())
