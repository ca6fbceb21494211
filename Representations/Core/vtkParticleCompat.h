/**
 * @file   vtkParticleCompat.h
 * @brief  The one place where the VTK versions ParticleRendering supports differ in C++.
 *
 * The project builds from one source tree against ParaView 5.11 (bundled VTK 9.2), 5.13
 * (bundled VTK 9.3) and 6.1 (external VTK 9.6); the CMake side of the differences is in the
 * top-level CMakeLists.txt and the modules' OPTIONAL_DEPENDS. Here:
 *  - the OpenGL loader: VTK up to 9.3 ships GLEW (`vtk_glew.h`, module VTK::glew), VTK 9.4
 *    and later glad (`vtk_glad.h`, module VTK::glad). Every file that calls OpenGL includes
 *    this header instead of either; the project calls no loader-specific function.
 *  - vtkPointGaussianMapper's bound scale (the peer of the benchmarks): `SetTriangleScale` up
 *    to VTK 9.3.0, `SetBoundScale` in the VTK development snapshots from 2023-10-25 on (as
 *    bundled with ParaView 5.13, VTK 9.3.20240617) and in 9.4; the old name is deprecated
 *    there and gone from 9.5.
 */
#ifndef vtkParticleCompat_h
#define vtkParticleCompat_h

#include "vtkVersionMacros.h"

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // VTK >= 9.4
#else
#include "vtk_glew.h" // VTK <= 9.3
#endif

/// Sets the size of vtkPointGaussianMapper's splat quad relative to the radius.
template <class TPointGaussianMapper>
inline void vtkParticleSetPointGaussianBoundScale(TPointGaussianMapper* mapper, float scale)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 20231025)
  mapper->SetBoundScale(scale);
#else
  mapper->SetTriangleScale(scale);
#endif
}

#endif
