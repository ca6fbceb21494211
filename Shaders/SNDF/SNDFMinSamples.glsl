#version 430
//=========================================================================
// SNDFMinSamples.glsl -- vtkSNDFRenderPass: the fewest samples any window
// pixel's S-NDF holds (prSums[3].y of its S-MIP texel; tile-list dispatches
// as SNDFAccumulate.glsl) into prMinimum, which the caller set to 0xFFFFFFFF. Refinement goes
// on until this reaches the target; it is counted after a pan or zoom has
// brought tiles of different sample counts into the view.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform ivec2 prSize;

//PR::Include SNDFBins
//PR::Include SNDFTiles

layout(std430, binding = 1) buffer prMinimumBuffer
{
  uint prMinimum;
};

shared uint prGroupMinimum;

void main()
{
  if (gl_LocalInvocationIndex == 0u)
  {
    prGroupMinimum = 0xFFFFFFFFu;
  }
  barrier();
  ivec2 p;
  uint texel;
  if (prSNDFTileInvocation(prSize, p, texel))
  {
    atomicMin(prGroupMinimum, uint(prSum(texel, 3u).y));
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u)
  {
    atomicMin(prMinimum, prGroupMinimum);
  }
}
