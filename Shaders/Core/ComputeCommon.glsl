//=========================================================================
// ComputeCommon.glsl -- helpers shared by the compute shaders.
//
// vtkParticleComputeProgram::Dispatch(x) splits more work groups than
// GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] into a 2D grid of at least x groups,
// so a shader that may be dispatched that wide uses prLinearGroupID() and
// leaves the groups at or above x idle.
//
// PR_BARRIER: a work-group barrier that also makes the shared-memory writes
// before it visible after it (GLSL 4.30 barrier() alone does not promise the
// latter).
//=========================================================================
#define PR_BARRIER memoryBarrierShared(); barrier()

uint prLinearGroupID()
{
  return gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
}

// The linear index of this invocation for one-dimensional work (a macro: gl_WorkGroupSize is only
// known after the shader's layout declaration).
#define PR_INVOCATION_INDEX (prLinearGroupID() * gl_WorkGroupSize.x + gl_LocalInvocationID.x)
