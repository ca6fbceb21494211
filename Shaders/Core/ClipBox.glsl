//=========================================================================
// ClipBox.glsl -- the clip box of vtkParticleSphereMapper::SetClipBox
// (distributed rendering: each process draws only its box of a k-d partition).
//
// Declared by the mapper when a box is set (PR_CLIP_BOX): prClipBoxAxes, the
// matrix from view-coordinate offsets to offsets in the position buffer's
// coordinates, and per sphere prBoxLoVSOutput / prBoxHiVSOutput, the box's
// corners relative to the sphere's centre in those coordinates (formed in the
// vertex stage from the centre and the box, so the tests are relative to the
// centre and keep their precision far from the origin).
//=========================================================================

// Whether a point (a view-coordinate offset from the centre) lies in the box.
bool prInsideClipBox(vec3 offsetVC)
{
  vec3 p = prClipBoxAxes * offsetVC;
  return all(greaterThanEqual(p, prBoxLoVSOutput)) && all(lessThanEqual(p, prBoxHiVSOutput));
}

// Narrow [un, uf], fractions of the segment from offset p0VC to offset p1VC (view coordinates,
// relative to the centre), to its part inside the box; clipN / clipF become true where an end
// moved. Returns false when nothing of [un, uf] is inside. Each face is a linear inequality
// along the segment.
bool prClipSegmentToBox(vec3 p0VC, vec3 p1VC, inout float un, inout float uf, inout bool clipN,
  inout bool clipF)
{
  vec3 p0 = prClipBoxAxes * p0VC;
  vec3 p1 = prClipBoxAxes * p1VC;
  for (int k = 0; k < 6; ++k)
  {
    int axis = k / 2;
    float g0 = (k % 2 == 0) ? p0[axis] - prBoxLoVSOutput[axis] : prBoxHiVSOutput[axis] - p0[axis];
    float g1 = (k % 2 == 0) ? p1[axis] - prBoxLoVSOutput[axis] : prBoxHiVSOutput[axis] - p1[axis];
    if (g0 < 0.0 && g1 < 0.0)
    {
      return false;
    }
    if (g0 < 0.0)
    {
      float u = g0 / (g0 - g1);
      if (u > un)
      {
        un = u;
        clipN = true;
      }
    }
    else if (g1 < 0.0)
    {
      float u = g0 / (g0 - g1);
      if (u < uf)
      {
        uf = u;
        clipF = true;
      }
    }
  }
  return uf > un;
}
