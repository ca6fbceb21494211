"""Render N random particles (the gas of make_particles.py: number density 0.1, constant radius
0.4, float32 positions generated in memory) with vtkParticleSphereMapper at 1024x768 and print the
time of the first frame (upload, culler build, draw) and of two more after camera moves, with the
number of particles the occlusion culler let through. For the 10^8-and-beyond rows of
Benchmarks/README.md.

usage: PYTHONPATH=build/lib/python3/dist-packages Scripts/with_xvfb.sh \\
           /usr/bin/time -v /usr/bin/python3 Benchmarks/large_counts.py 1e8
"""
import sys
import time

import numpy as np

import particlerendering as pr
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

N = int(float(sys.argv[1]))
start = time.time()
side = (N / 0.1) ** (1.0 / 3.0)
positions = np.random.default_rng(1).random((N, 3), dtype=np.float32) * side
points = vtkPoints()
points.SetData(numpy_to_vtk(positions, deep=False))
particles = vtkPolyData()
particles.SetPoints(points)
print("data %.1f s" % (time.time() - start), flush=True)
mapper = pr.vtkParticleSphereMapper()
mapper.SetInputData(particles)
mapper.SetRadius(0.4)
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(1024, 768)
window.AddRenderer(renderer)
renderer.ResetCamera()
for i in range(3):
    start = time.time()
    window.Render()
    print("frame %d %.2f s, uploads %d, stride %d, particles past the cell culling %d" % (
        i, time.time() - start, mapper.GetNumberOfUploads(), mapper.GetParticleStride(),
        mapper.GetOcclusionCuller().GetLastNumberOfDrawnParticles()), flush=True)
    renderer.GetActiveCamera().Azimuth(10.0)
