#version 430
//=========================================================================
// SNDFImageDifference.glsl -- vtkSNDFRenderPass: the summed absolute
// difference of two pictures (rgb, in 1/(255 * 64) units), for the error
// estimate that stops refinement at an error target: the picture after N
// samples against the one after M < N, |I_N - I_M| (see the class comment).
// Each work group adds its sum to one of the 1024 counters of prTotals
// (group number modulo 1024, so that no counter overflows below 8K x 8K);
// the caller zeroes them and adds them up.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform ivec2 prSize;
layout(rgba32f, binding = 0) uniform readonly image2D prImage;
layout(rgba32f, binding = 1) uniform readonly image2D prBefore;
layout(std430, binding = 1) buffer prTotalBuffer
{
  uint prTotals[];
};

shared uint prGroupTotal;

void main()
{
  if (gl_LocalInvocationIndex == 0u)
  {
    prGroupTotal = 0u;
  }
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x < prSize.x && p.y < prSize.y)
  {
    vec3 d = abs(imageLoad(prImage, p).rgb - imageLoad(prBefore, p).rgb);
    atomicAdd(prGroupTotal, uint(min(dot(d, vec3(1.0)), 3.0) * (255.0 * 64.0) + 0.5));
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u)
  {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    atomicAdd(prTotals[group % 1024u], prGroupTotal);
  }
}
