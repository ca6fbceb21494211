//=========================================================================
// SNDFLightingTable.glsl -- vtkSNDFRenderPass: the lighting table of the
// S-NDF bins (Ibrahim et al. 2017, Eqs. 12-14), drawn into a (bins^2 x 2)
// float target: texel (b, 0) is the mean over the normals of bin b (the bin
// ∩ unit disk, uniform in the projected (x, y), the measure a uniformly hit
// sphere gives) of VTK's diffuse light sum, texel (b, 1) of its specular sum.
// The light sums come from vtkParticleSphereMapper::GetLightSumCode, i.e.
// the same GLSL the sphere mapper shades with (Lighting.glsl). The surface
// point is on the view axis at the focal distance (view vector +z).
// Spliced into VTK's full-screen-quad template (//VTK::FSQ::Decl, Impl).
//=========================================================================
//PR::Include SNDFBins
//PR::Include Lighting
uniform int prBins;
uniform int prTableRows;
uniform int prSubsamples;
uniform float prSpecularPower;
uniform float prViewDistance;
