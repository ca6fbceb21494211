//=========================================================================
// DensityVolumeOwn.glsl -- the share of a particle's own splat in a trilinear
// fetch of the density volume (vtkParticleDensityVolume, vtkDensityVolumeAOPass
// per-sphere retrieval). Coordinates are volume texture coordinates [0,1]^3;
// dims the voxel counts. The splat puts a particle at p into the voxel holding
// p (nearest voxel) or into the 8 voxels around it with tent weights (cloud in
// cell, "trilinear"); a linear-filtered fetch at q weighs the voxel centred at
// c by the tent 1 - |q - c| (in voxels) on each axis. Both are products over
// the axes, so the share is the product of the 1-D sums over the (at most two)
// voxels the particle touched. Multiplied by the particle's density
// contribution it is what the particle itself adds to the fetched value
// (before the volume's clamp to 1). Grid boundaries, where the splat folds
// corners onto the edge voxels, are not modelled: a sphere there keeps a little
// of its own density.
//=========================================================================
float prOwnDensityWeight1D(float p, float q, bool trilinear)
{
  if (!trilinear)
  {
    float c = floor(p) + 0.5;
    return max(0.0, 1.0 - abs(q - c));
  }
  float v = p - 0.5;
  float f = floor(v);
  float w = v - f;
  return (1.0 - w) * max(0.0, 1.0 - abs(q - (f + 0.5))) + w * max(0.0, 1.0 - abs(q - (f + 1.5)));
}

float prOwnDensityWeight(vec3 pVolume, vec3 qVolume, vec3 dims, bool trilinear)
{
  vec3 p = pVolume * dims;
  vec3 q = qVolume * dims;
  return prOwnDensityWeight1D(p.x, q.x, trilinear) * prOwnDensityWeight1D(p.y, q.y, trilinear) *
    prOwnDensityWeight1D(p.z, q.z, trilinear);
}
