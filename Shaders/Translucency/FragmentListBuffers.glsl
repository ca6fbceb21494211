//=========================================================================
// FragmentListBuffers.glsl -- the per-pixel lists of translucent sphere
// segments of vtkParticleFragmentLists (exact compositing of overlapping
// spheres, vtkTransparentSphereMapper's EXACT_OVERLAP), shared by the
// fragment stage that appends to them and the pass that resolves them.
//
// Needs GL_ARB_shader_storage_buffer_object (core in OpenGL 4.3), enabled
// after the #version line by the user. Binding points are set from the CPU
// (glShaderStorageBlockBinding), so no GLSL 4.20 layout(binding) is needed.
//
// A node is PR_LIST_NODE_UINTS 32-bit words:
//   0 key of the closest approach along the pixel ray (common to all spheres)
//   1 radius (view coordinates)
//   2, 3 the visible segment [tn, tf] in radii from the closest approach
//   4 squared impact parameter in radii^2
//   5 kappa / I_max (optical depth per unit density integral); 1e30: opaque
//   6, 7, 8 the emitted colour (r, g, b)
//   9 next node (0xffffffff: end)
//=========================================================================
#define PR_LIST_NODE_UINTS 10
#define PR_LIST_END 0xffffffffu

layout(std430) buffer prListHeadBlock
{
  uint prListHeads[];
};
layout(std430) buffer prListNodeBlock
{
  uint prListNodes[];
};
// [0] nodes appended (may exceed the capacity: the overflow is counted, not stored),
// [1] pixels whose lists could not be composited completely (resolve), [2] pixels deferred to
// the resolve's second pass
layout(std430) buffer prListCounterBlock
{
  uint prListCounters[];
};
// the pixels (y * width + x) of the resolve's second pass
layout(std430) buffer prListDeferredBlock
{
  uint prListDeferred[];
};
// pixels per row of the head array and the node capacity
uniform int prListWidth;
uniform int prListCapacity;
