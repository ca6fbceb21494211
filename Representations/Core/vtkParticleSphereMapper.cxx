#include "vtkParticleSphereMapper.h"
#include "vtkParticleEmissionModel.h"
#include "vtkParticleFrameBudget.h"
#include "vtkParticleOcclusionCuller.h"

#include "vtkActor.h"
#include "vtkArrayDispatch.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkLightingMapPass.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleShaders.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTimerLog.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkParticleSphereMapper);

//------------------------------------------------------------------------------
class vtkParticleSphereMapper::vtkInternals
{
public:
  // Sanitised per-particle data, rebuilt when the input or the radius settings change.
  vtkNew<vtkFloatArray> Radii; // MC radius, 0 for skipped particles
  // ellipsoids (Shape ELLIPSOID with a usable axes array): semi-axes and unit quaternions, and
  // whether the program in use was built for them
  vtkNew<vtkFloatArray> Axes;
  vtkNew<vtkFloatArray> Orientations;
  vtkNew<vtkFloatArray> VolumeRadii; // cbrt(a b c), 0 for skipped particles
  vtkSmartPointer<vtkDataArray> UploadedVolumeRadii;
  bool Ellipsoids = false;
  // per program (a subclass draws several, e.g. opaque and translucent): whether it was built
  // for ellipsoids
  std::map<const vtkOpenGLHelper*, bool> BuiltEllipsoids;
  // The positions uploaded: the input's own point array when every particle is valid (no copy),
  // else a copy in the input's precision with the skipped particles moved onto a valid one. The
  // VBO converts to float after its shift/scale, so far-from-origin data keeps its precision.
  vtkSmartPointer<vtkDataArray> Positions;
  vtkNew<vtkParticleOcclusionCuller> Culler;
  vtkNew<vtkMatrix4x4> DrawWCDC; // see SetCameraShaderParameters
  // what the vertex buffers hold: the arrays above, or every Stride-th of them
  vtkIdType Stride = 1;
  vtkSmartPointer<vtkDataArray> UploadedPositions;
  vtkSmartPointer<vtkFloatArray> UploadedRadii;
  vtkSmartPointer<vtkDataArray> UploadedAxes;
  vtkSmartPointer<vtkDataArray> UploadedOrientations;
  std::vector<vtkSmartPointer<vtkDataArray>> StrideArrays; // alive until the next upload
  std::string LastStrideWarning;
  vtkTimeStamp CullerBuildTime;
  double CenterBounds[6] = { 0, -1, 0, -1, 0, -1 };
  double MaxRadius = 0.0;
  double MinRadius = 0.0;       // smallest drawn radius (MC)
  bool FocalPointShift = false; // positions uploaded relative to the camera's focal point
  bool CentreShift = false;     // positions uploaded relative to their bounds' centre
  std::string LastShiftWarning;
  std::string LastPrecisionWarning;
  vtkIdType NumberOfPoints = 0;
  vtkMTimeType PrepareTime = 0;
  // what the prepared particles were computed from (see PrepareParticles)
  struct Signature
  {
    vtkPolyData* Input = nullptr;
    vtkDataArray* Points = nullptr;
    vtkMTimeType PointsTime = 0;
    vtkAbstractArray* RadiusArray = nullptr;
    vtkMTimeType RadiusTime = 0;
    std::string RadiusArrayName;
    double Radius = 0.0;
    vtkIdType NumberOfPoints = -1;
    // ellipsoids
    int Shape = 0;
    vtkAbstractArray* AxesArray = nullptr;
    vtkMTimeType AxesTime = 0;
    std::string AxesArrayName;
    int AxesComponent = 0;
    bool AxesAreDiameters = false;
    vtkAbstractArray* OrientationArray = nullptr;
    vtkMTimeType OrientationTime = 0;
    std::string OrientationArrayName;
    int OrientationComponent = 0;
    vtkAbstractArray* TensorArray = nullptr;
    vtkMTimeType TensorTime = 0;
    std::string TensorArrayName;
    bool operator==(const Signature& o) const
    {
      return Input == o.Input && Points == o.Points && PointsTime == o.PointsTime &&
        RadiusArray == o.RadiusArray && RadiusTime == o.RadiusTime &&
        RadiusArrayName == o.RadiusArrayName && Radius == o.Radius &&
        NumberOfPoints == o.NumberOfPoints && Shape == o.Shape && AxesArray == o.AxesArray &&
        AxesTime == o.AxesTime && AxesArrayName == o.AxesArrayName &&
        AxesComponent == o.AxesComponent && AxesAreDiameters == o.AxesAreDiameters &&
        OrientationArray == o.OrientationArray && OrientationTime == o.OrientationTime &&
        OrientationArrayName == o.OrientationArrayName &&
        OrientationComponent == o.OrientationComponent && TensorArray == o.TensorArray &&
        TensorTime == o.TensorTime && TensorArrayName == o.TensorArrayName;
    }
  };
  Signature Prepared;
  // the last warning given, so that a warning is said once per input change, not every frame
  std::string LastWarning;
  // the input the buffers were built from
  vtkPolyData* BuiltInput = nullptr;
  // selection: the first vertex cell holding each point (-1: none)
  std::vector<vtkIdType> VertexCellOfPoint;
  vtkTimeStamp VertexCellOfPointTime;
  // GPU timer query around the draw call (CollectTimings)
  vtkOpenGLRenderTimer DrawTimer;
  // the quality ladder of subclasses with cheaper levels
  vtkNew<vtkParticleFrameBudget> FrameBudget;
};

//------------------------------------------------------------------------------
vtkParticleSphereMapper::vtkParticleSphereMapper()
  : Internals(new vtkInternals)
{
  this->Internals->Radii->SetName("ParticleRadius");
  this->Internals->Axes->SetName("ParticleAxes");
  this->Internals->Axes->SetNumberOfComponents(3);
  this->Internals->Orientations->SetName("ParticleOrientation");
  this->Internals->Orientations->SetNumberOfComponents(4);
}

//------------------------------------------------------------------------------
vtkParticleSphereMapper::~vtkParticleSphereMapper()
{
  this->SetRadiusArrayName(nullptr);
  this->SetAxesArrayName(nullptr);
  this->SetOrientationArrayName(nullptr);
  this->SetTensorArrayName(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
namespace
{
// progress of an upload after validation and after colour mapping (see BuildBufferObjects)
constexpr double UploadProgressValidated = 0.15;
constexpr double UploadProgressColoured = 0.3;

struct ParticleSummary
{
  double Bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  double MaxRadius = 0.0;
  double MinRadius = VTK_DOUBLE_MAX;
  vtkIdType BadRadius = 0;
  vtkIdType BadPosition = 0;
  vtkIdType HugeRadius = 0;   // finite, but beyond single precision (of BadRadius)
  vtkIdType HugePosition = 0; // likewise (of BadPosition)
  vtkIdType FirstValid = -1;
};

// Every particle checked (finite position and radius within single precision), radii[i] its
// radius or 0 where it is skipped, with the counts, bounds and radius range of the valid ones.
ParticleSummary CheckParticles(vtkDataArray* points, vtkDataArray* radiusArray,
  double constantRadius, float* radii, vtkIdType numPts)
{
  vtkSMPThreadLocal<ParticleSummary> local;
  vtkSMPTools::For(0, numPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      ParticleSummary& s = local.Local();
      double p[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        points->GetTuple(i, p);
        const double r = radiusArray ? radiusArray->GetComponent(i, 0) : constantRadius;
        const bool finitePosition =
          std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
        const bool goodPosition =
          finitePosition && std::abs(p[0]) < 1e37 && std::abs(p[1]) < 1e37 && std::abs(p[2]) < 1e37;
        const bool goodRadius = std::isfinite(r) && r > 0.0 && r < 1e37;
        if (!goodPosition)
        {
          ++s.BadPosition;
          s.HugePosition += finitePosition ? 1 : 0;
        }
        else if (!goodRadius)
        {
          ++s.BadRadius;
          s.HugeRadius += (std::isfinite(r) && r > 0.0) ? 1 : 0;
        }
        if (goodPosition && goodRadius)
        {
          radii[i] = static_cast<float>(r);
          for (int k = 0; k < 3; ++k)
          {
            s.Bounds[2 * k] = std::min(s.Bounds[2 * k], p[k]);
            s.Bounds[2 * k + 1] = std::max(s.Bounds[2 * k + 1], p[k]);
          }
          s.MaxRadius = std::max(s.MaxRadius, r);
          s.MinRadius = std::min(s.MinRadius, r);
          if (s.FirstValid < 0 || i < s.FirstValid)
          {
            s.FirstValid = i;
          }
        }
        else
        {
          radii[i] = 0.0f;
        }
      }
    });
  ParticleSummary total;
  for (const ParticleSummary& s : local)
  {
    for (int k = 0; k < 3; ++k)
    {
      total.Bounds[2 * k] = std::min(total.Bounds[2 * k], s.Bounds[2 * k]);
      total.Bounds[2 * k + 1] = std::max(total.Bounds[2 * k + 1], s.Bounds[2 * k + 1]);
    }
    total.MaxRadius = std::max(total.MaxRadius, s.MaxRadius);
    total.MinRadius = std::min(total.MinRadius, s.MinRadius);
    total.BadRadius += s.BadRadius;
    total.BadPosition += s.BadPosition;
    total.HugeRadius += s.HugeRadius;
    total.HugePosition += s.HugePosition;
    if (s.FirstValid >= 0 && (total.FirstValid < 0 || s.FirstValid < total.FirstValid))
    {
      total.FirstValid = s.FirstValid;
    }
  }
  return total;
}

// A copy of the positions in which each skipped particle (radius 0) has the position of the
// first valid one, so that no NaN reaches the GPU and the VBO's automatic shift/scale sees only
// real coordinates.
vtkSmartPointer<vtkDataArray> FillSkipped(
  vtkDataArray* points, const float* radii, vtkIdType firstValid, vtkIdType numPts)
{
  vtkSmartPointer<vtkDataArray> copy;
  copy.TakeReference(points->NewInstance());
  copy->SetNumberOfComponents(3);
  copy->SetNumberOfTuples(numPts);
  double fill[3] = { 0.0, 0.0, 0.0 };
  if (firstValid >= 0)
  {
    points->GetTuple(firstValid, fill);
  }
  vtkSMPTools::For(0, numPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      double p[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (radii[i] == 0.0f)
        {
          copy->SetTuple(i, fill);
        }
        else
        {
          points->GetTuple(i, p);
          copy->SetTuple(i, p);
        }
      }
    });
  return copy;
}

// The point array `name` of `input` when it is numeric; otherwise nullptr and the reason appended
// to `warnings` as "<role> array '<name>' is not a point array of the input / is not numeric:
// <fallback>. " (nullptr without a warning when no name is given).
vtkDataArray* NumericPointArray(vtkPolyData* input, const char* name, const char* role,
  const std::string& fallback, std::ostream& warnings)
{
  if (!input || !name || !name[0])
  {
    return nullptr;
  }
  vtkAbstractArray* abstractArray = input->GetPointData()->GetAbstractArray(name);
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstractArray);
  if (!abstractArray)
  {
    warnings << role << " array '" << name << "' is not a point array of the input: " << fallback
             << ". ";
  }
  else if (!array)
  {
    warnings << role << " array '" << name << "' is not numeric (" << abstractArray->GetClassName()
             << "): " << fallback << ". ";
  }
  return array;
}

// The numeric point array `name` of `input` when it has at least first + count components;
// otherwise nullptr and the reason appended to `warnings` (nullptr without a warning when no name
// is given).
vtkDataArray* GetComponentsPointArray(vtkPolyData* input, const char* name, const char* role,
  int first, int count, const std::string& fallback, std::ostream& warnings)
{
  vtkDataArray* array = NumericPointArray(input, name, role, fallback, warnings);
  if (array && array->GetNumberOfComponents() < first + count)
  {
    warnings << role << " array '" << name << "' has " << array->GetNumberOfComponents()
             << " components, components " << first << " to " << first + count - 1
             << " are needed: " << fallback << ". ";
    array = nullptr;
  }
  return array;
}

// The semi-axes (absolute eigenvalues of the symmetric part) and unit quaternions (the
// eigenvectors, right-handed) of 3x3 tensors, as vtkTensorGlyph's ExtractEigenvalues reads them;
// a non-finite tensor gives NaN axes, an eigenvalue below 1e-6 of the largest 0 (the particle
// is then skipped as for bad axes).
void TensorsToEllipsoids(vtkDataArray* tensors, vtkFloatArray* axes, vtkFloatArray* quaternions)
{
  const vtkIdType n = tensors->GetNumberOfTuples();
  axes->SetNumberOfComponents(3);
  axes->SetNumberOfTuples(n);
  quaternions->SetNumberOfComponents(4);
  quaternions->SetNumberOfTuples(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      double t[9];
      for (vtkIdType i = begin; i < end; ++i)
      {
        tensors->GetTuple(i, t);
        double m[3][3];
        bool finite = true;
        for (int r = 0; r < 3; ++r)
        {
          for (int c = 0; c < 3; ++c)
          {
            m[r][c] = 0.5 * (t[r + 3 * c] + t[c + 3 * r]);
            finite = finite && std::isfinite(m[r][c]);
          }
        }
        double w[3] = { 0.0, 0.0, 0.0 };
        double v[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
        if (finite)
        {
          vtkMath::Diagonalize3x3(m, w, v); // eigenvectors in the columns of v
          if (vtkMath::Determinant3x3(v) < 0.0)
          {
            for (int r = 0; r < 3; ++r)
            {
              v[r][2] = -v[r][2];
            }
          }
        }
        // an eigenvalue below float precision of the largest is a flat glyph's 0 (skipped)
        const double largest = std::max({ std::abs(w[0]), std::abs(w[1]), std::abs(w[2]) });
        for (double& value : w)
        {
          value = std::abs(value) > 1e-6 * largest ? value : 0.0;
        }
        double q[4];
        vtkMath::Matrix3x3ToQuaternion(v, q);
        for (int k = 0; k < 3; ++k)
        {
          axes->SetTypedComponent(
            i, k, finite ? static_cast<float>(std::abs(w[k])) : std::nanf(""));
        }
        for (int k = 0; k < 4; ++k)
        {
          quaternions->SetTypedComponent(i, k, static_cast<float>(q[k]));
        }
      }
    });
}

struct EllipsoidSummary
{
  vtkIdType BadAxes = 0;
  vtkIdType BadOrientation = 0;
  vtkIdType NonUnitOrientation = 0;
  double WorstLength = 1.0; // the quaternion length furthest from 1 among the non-unit ones
};

// Semi-axes (halved diameters) and unit quaternions of every particle; boundingRadii[i] the
// largest semi-axis, NaN when an axis is zero, negative, not finite or beyond single precision
// (the particle is then skipped as for a bad radius).
EllipsoidSummary CheckEllipsoids(vtkDataArray* axesArray, int axesComponent, bool diameters,
  vtkDataArray* orientationArray, int orientationComponent, float* axes, float* quaternions,
  float* boundingRadii, vtkIdType numPts)
{
  vtkSMPThreadLocal<EllipsoidSummary> local;
  const double axisFactor = diameters ? 0.5 : 1.0;
  vtkSMPTools::For(0, numPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      EllipsoidSummary& s = local.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        bool good = true;
        double largest = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          const double a = axisFactor * axesArray->GetComponent(i, axesComponent + k);
          good = good && std::isfinite(a) && a > 0.0 && a < 1e37;
          axes[3 * i + k] = good ? static_cast<float>(a) : 0.0f;
          largest = std::max(largest, a);
        }
        if (!good)
        {
          ++s.BadAxes;
          axes[3 * i] = axes[3 * i + 1] = axes[3 * i + 2] = 0.0f;
        }
        boundingRadii[i] = good ? static_cast<float>(largest) : std::nanf("");
        double q[4] = { 1.0, 0.0, 0.0, 0.0 };
        if (orientationArray)
        {
          for (int k = 0; k < 4; ++k)
          {
            q[k] = orientationArray->GetComponent(i, orientationComponent + k);
          }
        }
        const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!std::isfinite(length) || !(length > 1e-30))
        {
          ++s.BadOrientation;
          q[0] = 1.0;
          q[1] = q[2] = q[3] = 0.0;
        }
        else
        {
          if (std::abs(length - 1.0) > 1e-3)
          {
            ++s.NonUnitOrientation;
            if (std::abs(length - 1.0) > std::abs(s.WorstLength - 1.0))
            {
              s.WorstLength = length;
            }
          }
          for (double& c : q)
          {
            c /= length;
          }
        }
        for (int k = 0; k < 4; ++k)
        {
          quaternions[4 * i + k] = static_cast<float>(q[k]);
        }
      }
    });
  EllipsoidSummary total;
  for (const EllipsoidSummary& s : local)
  {
    total.BadAxes += s.BadAxes;
    total.BadOrientation += s.BadOrientation;
    total.NonUnitOrientation += s.NonUnitOrientation;
    if (std::abs(s.WorstLength - 1.0) > std::abs(total.WorstLength - 1.0))
    {
      total.WorstLength = s.WorstLength;
    }
  }
  return total;
}

// The warnings for skipped particles, by cause.
void ReportSkipped(
  const ParticleSummary& total, vtkIdType numPts, bool ellipsoids, std::ostream& warnings)
{
  // (1e37: beyond it the GPU's single precision overflows in the squares of the intersection)
  if (total.BadPosition > total.HugePosition)
  {
    warnings << total.BadPosition - total.HugePosition << " of " << numPts
             << " particles have a NaN or infinite position and are not drawn. ";
  }
  if (total.HugePosition > 0)
  {
    warnings << total.HugePosition << " of " << numPts
             << " particles have a coordinate of 1e37 or more, too large for single "
                "precision, and are not drawn. ";
  }
  if (ellipsoids)
  {
    if (total.BadRadius > 0)
    {
      warnings << total.BadRadius << " of " << numPts
               << " particles have a semi-axis that is zero, negative, NaN, infinite or 1e37 or "
                  "more, and are not drawn. ";
    }
    return;
  }
  if (total.BadRadius > total.HugeRadius)
  {
    warnings << total.BadRadius - total.HugeRadius << " of " << numPts
             << " particles have a zero, negative, NaN or infinite radius and are not drawn. ";
  }
  if (total.HugeRadius > 0)
  {
    warnings << total.HugeRadius << " of " << numPts
             << " particles have a radius of 1e37 or more, too large for single precision, "
                "and are not drawn. ";
  }
}
}

vtkIdType vtkParticleSphereMapper::PrepareParticles()
{
  vtkPolyData* input = this->GetInput();
  vtkInternals& internals = *this->Internals;
  vtkIdType numPts = (input && input->GetPoints()) ? input->GetNumberOfPoints() : 0;

  // Recomputed only when the positions or the radius source changed: colour, opacity or shading
  // settings (which modify the mapper) keep the prepared particles, their buffers and any sort.
  vtkInternals::Signature signature;
  signature.Input = input;
  signature.Points = numPts > 0 ? input->GetPoints()->GetData() : nullptr;
  signature.PointsTime = signature.Points ? signature.Points->GetMTime() : 0;
  signature.RadiusArrayName = this->RadiusArrayName ? this->RadiusArrayName : "";
  signature.RadiusArray = (numPts > 0 && !signature.RadiusArrayName.empty())
    ? input->GetPointData()->GetAbstractArray(this->RadiusArrayName)
    : nullptr;
  signature.RadiusTime = signature.RadiusArray ? signature.RadiusArray->GetMTime() : 0;
  signature.Radius = this->Radius;
  signature.NumberOfPoints = numPts;
  signature.Shape = this->Shape;
  if (this->Shape == ELLIPSOID && numPts > 0)
  {
    vtkPointData* pd = input->GetPointData();
    signature.AxesArrayName = this->AxesArrayName ? this->AxesArrayName : "";
    signature.AxesArray =
      signature.AxesArrayName.empty() ? nullptr : pd->GetAbstractArray(this->AxesArrayName);
    signature.AxesTime = signature.AxesArray ? signature.AxesArray->GetMTime() : 0;
    signature.AxesComponent = this->AxesArrayComponent;
    signature.AxesAreDiameters = this->AxesAreDiameters;
    signature.OrientationArrayName = this->OrientationArrayName ? this->OrientationArrayName : "";
    signature.OrientationArray = signature.OrientationArrayName.empty()
      ? nullptr
      : pd->GetAbstractArray(this->OrientationArrayName);
    signature.OrientationTime =
      signature.OrientationArray ? signature.OrientationArray->GetMTime() : 0;
    signature.OrientationComponent = this->OrientationArrayComponent;
    signature.TensorArrayName = this->TensorArrayName ? this->TensorArrayName : "";
    signature.TensorArray =
      signature.TensorArrayName.empty() ? nullptr : pd->GetAbstractArray(this->TensorArrayName);
    signature.TensorTime = signature.TensorArray ? signature.TensorArray->GetMTime() : 0;
  }
  if (internals.PrepareTime != 0 && internals.Prepared == signature)
  {
    return numPts;
  }
  internals.Prepared = signature;
  internals.NumberOfPoints = numPts;
  internals.PrepareTime = 0;

  std::ostringstream warnings;
  if (numPts == 0)
  {
    warnings << "The input has no points: nothing to draw.";
    internals.Radii->SetNumberOfTuples(0);
    internals.Ellipsoids = false;
    internals.Axes->SetNumberOfTuples(0);
    internals.Orientations->SetNumberOfTuples(0);
    internals.Positions = nullptr;
    internals.MaxRadius = 0.0;
    vtkMath::UninitializeBounds(internals.CenterBounds);
    this->NumberOfSkippedParticles = 0;
  }
  else
  {
    // Which radius source?
    std::ostringstream fallback;
    fallback << "using the constant radius " << this->Radius;
    vtkDataArray* radiusArray = nullptr;
    // Ellipsoids: their largest semi-axes are the radii (bounds, culling, clip boxes)
    vtkNew<vtkFloatArray> boundingRadii;
    const bool haveAxes = this->PrepareEllipsoids(input, boundingRadii, warnings);
    // (a surface of its own, e.g. metaballs, is made of spheres: those of the largest semi-axes)
    internals.Ellipsoids = haveAxes && this->GetDrawsSphereGlyphs();
    if (haveAxes && !internals.Ellipsoids)
    {
      warnings << "A " << this->GetClassName()
               << " draws a surface of spheres, not ellipsoids: each particle's largest "
                  "semi-axis is its radius. ";
    }
    if (haveAxes)
    {
      radiusArray = boundingRadii;
    }
    else
    {
      radiusArray =
        GetScalarPointArray(input, this->RadiusArrayName, "Radius", fallback.str(), warnings);
    }

    vtkDataArray* points = input->GetPoints()->GetData();
    internals.Radii->SetNumberOfTuples(numPts);
    float* radii = internals.Radii->GetPointer(0);

    const ParticleSummary total = CheckParticles(points, radiusArray, this->Radius, radii, numPts);
    if (internals.Ellipsoids && total.BadPosition > 0)
    {
      // skipped for their position: no axes either (GetParticleAxes() says 0 for skipped)
      float* axes = internals.Axes->GetPointer(0);
      for (vtkIdType i = 0; i < numPts; ++i)
      {
        if (radii[i] == 0.0f)
        {
          axes[3 * i] = axes[3 * i + 1] = axes[3 * i + 2] = 0.0f;
        }
      }
    }
    if (internals.Ellipsoids)
    {
      // the radius of the sphere of each ellipsoid's volume
      const float* axes = internals.Axes->GetPointer(0);
      internals.VolumeRadii->SetNumberOfTuples(numPts);
      float* volumeRadii = internals.VolumeRadii->GetPointer(0);
      vtkSMPTools::For(0, numPts,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            volumeRadii[i] = radii[i] > 0.0f
              ? static_cast<float>(
                  std::cbrt(static_cast<double>(axes[3 * i]) * axes[3 * i + 1] * axes[3 * i + 2]))
              : 0.0f;
          }
        });
      internals.VolumeRadii->Modified();
    }
    // written through a raw pointer: tell the VBO cache the values are new
    internals.Radii->Modified();

    // Skipped particles get the position of a valid one (radius 0 keeps them invisible), so that
    // no NaN reaches the GPU and the VBO's automatic shift/scale sees only real coordinates.
    const vtkIdType skipped = total.BadRadius + total.BadPosition;
    if (skipped == 0)
    {
      internals.Positions = points;
    }
    else
    {
      internals.Positions = FillSkipped(points, radii, total.FirstValid, numPts);
    }
    ReportSkipped(total, numPts, internals.Ellipsoids, warnings);
    this->NumberOfSkippedParticles = skipped;
    internals.MaxRadius = total.MaxRadius;
    internals.MinRadius = total.FirstValid >= 0 ? total.MinRadius : 0.0;
    if (total.FirstValid >= 0)
    {
      std::copy(total.Bounds, total.Bounds + 6, internals.CenterBounds);
    }
    else
    {
      vtkMath::UninitializeBounds(internals.CenterBounds);
    }
  }

  this->WarnOnChange(warnings.str(), internals.LastWarning);
  // a real modification stamp, later than the input's and the mapper's
  vtkTimeStamp stamp;
  stamp.Modified();
  internals.PrepareTime = stamp.GetMTime();
  return numPts;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::PrepareEllipsoids(
  vtkPolyData* input, vtkFloatArray* boundingRadii, std::ostream& warnings)
{
  vtkInternals& internals = *this->Internals;
  internals.Axes->SetNumberOfTuples(0);
  internals.Orientations->SetNumberOfTuples(0);
  if (this->Shape != ELLIPSOID)
  {
    return false;
  }
  const vtkIdType numPts = input->GetNumberOfPoints();
  vtkDataArray* axesArray = nullptr;
  vtkDataArray* orientationArray = nullptr;
  int axesComponent = this->AxesArrayComponent;
  int orientationComponent = this->OrientationArrayComponent;
  bool diameters = this->AxesAreDiameters;
  vtkNew<vtkFloatArray> tensorAxes;
  vtkNew<vtkFloatArray> tensorQuaternions;
  if (this->TensorArrayName && this->TensorArrayName[0])
  {
    // axes and orientation from the tensors' eigen-decomposition (vtkTensorGlyph's rule)
    vtkDataArray* tensors = GetComponentsPointArray(
      input, this->TensorArrayName, "Tensor", 0, 9, "drawing spheres", warnings);
    if (!tensors)
    {
      return false;
    }
    TensorsToEllipsoids(tensors, tensorAxes, tensorQuaternions);
    axesArray = tensorAxes;
    orientationArray = tensorQuaternions;
    axesComponent = 0;
    orientationComponent = 0;
    diameters = false;
  }
  else
  {
    if (!this->AxesArrayName || !this->AxesArrayName[0])
    {
      warnings << "Shape is Ellipsoid but no axes array is set: drawing spheres. ";
    }
    else
    {
      axesArray = GetComponentsPointArray(input, this->AxesArrayName, "Axes",
        this->AxesArrayComponent, 3, "drawing spheres", warnings);
    }
    if (!axesArray)
    {
      return false;
    }
    orientationArray = GetComponentsPointArray(input, this->OrientationArrayName, "Orientation",
      this->OrientationArrayComponent, 4, "drawing the ellipsoids axis-aligned", warnings);
  }
  internals.Axes->SetNumberOfTuples(numPts);
  internals.Orientations->SetNumberOfTuples(numPts);
  boundingRadii->SetNumberOfTuples(numPts);
  const EllipsoidSummary summary = CheckEllipsoids(axesArray, axesComponent, diameters,
    orientationArray, orientationComponent, internals.Axes->GetPointer(0),
    internals.Orientations->GetPointer(0), boundingRadii->GetPointer(0), numPts);
  internals.Axes->Modified();
  internals.Orientations->Modified();
  if (summary.BadOrientation > 0)
  {
    warnings << summary.BadOrientation << " of " << numPts
             << " particles have a zero, NaN or infinite orientation quaternion: drawn "
                "axis-aligned. ";
  }
  if (summary.NonUnitOrientation > 0)
  {
    warnings << summary.NonUnitOrientation << " of " << numPts
             << " particles have an orientation quaternion whose length is not 1 (up to "
             << summary.WorstLength << "): normalised. ";
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetDrawsEllipsoids()
{
  this->PrepareParticles();
  return this->Internals->Ellipsoids;
}

//------------------------------------------------------------------------------
vtkFloatArray* vtkParticleSphereMapper::GetParticleVolumeRadii()
{
  this->PrepareParticles();
  return this->Internals->Ellipsoids ? this->Internals->VolumeRadii.GetPointer()
                                     : this->Internals->Radii.GetPointer();
}

//------------------------------------------------------------------------------
vtkFloatArray* vtkParticleSphereMapper::GetParticleAxes()
{
  this->PrepareParticles();
  return this->Internals->Ellipsoids ? this->Internals->Axes.GetPointer() : nullptr;
}

//------------------------------------------------------------------------------
vtkFloatArray* vtkParticleSphereMapper::GetParticleOrientations()
{
  this->PrepareParticles();
  return this->Internals->Ellipsoids ? this->Internals->Orientations.GetPointer() : nullptr;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetRadiusScaleFactor(double factor)
{
  if (factor == this->RadiusScaleFactor)
  {
    return;
  }
  const vtkMTimeType before = this->GetParticleDataMTime();
  this->RadiusScaleFactor = factor;
  this->Modified();
  this->ScaleOnlyMTime = this->GetMTime();
  this->DataMTimeBeforeScale = before;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetPositionBounds(const double bounds[6])
{
  if (!std::equal(bounds, bounds + 6, this->PositionBounds))
  {
    std::copy(bounds, bounds + 6, this->PositionBounds);
    this->Modified(); // the buffers are uploaded again
  }
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::GetPositionBounds(double bounds[6])
{
  std::copy(this->PositionBounds, this->PositionBounds + 6, bounds);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkParticleSphereMapper::GetParticleDataMTime()
{
  const vtkMTimeType mtime = this->GetMTime();
  return mtime == this->ScaleOnlyMTime ? this->DataMTimeBeforeScale : mtime;
}

//------------------------------------------------------------------------------
double* vtkParticleSphereMapper::GetBounds()
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  if (!this->Static)
  {
    this->Update();
  }
  this->PrepareParticles();
  const vtkInternals& internals = *this->Internals;
  if (!vtkMath::AreBoundsInitialized(internals.CenterBounds))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  const double grow = internals.MaxRadius * std::abs(this->RadiusScaleFactor);
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] = internals.CenterBounds[2 * k] - grow;
    this->Bounds[2 * k + 1] = internals.CenterBounds[2 * k + 1] + grow;
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetParticleBuffers(vtkOpenGLBufferObject*& positions,
  unsigned int& positionStride, vtkOpenGLBufferObject*& radii, vtkIdType& count,
  vtkMatrix4x4* bufferToModel)
{
  vtkOpenGLVertexBufferObject* positionVBO = this->VBOs->GetVBO("vertexMC");
  vtkOpenGLVertexBufferObject* radiusVBO =
    this->VBOs->GetVBO(this->Internals->Ellipsoids ? "volumeRadiusMC" : "radiusMC");
  count = static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount);
  if (!positionVBO || !radiusVBO || count <= 0 || positionVBO->GetHandle() == 0)
  {
    return false;
  }
  positions = positionVBO;
  positionStride = positionVBO->GetStride() / sizeof(float);
  radii = radiusVBO;
  vtkMatrix4x4::Transpose(this->VBOShiftScale, bufferToModel); // stored transposed
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkParticleSphereMapper::GetScalarPointArray(vtkPolyData* input, const char* name,
  const char* role, const std::string& fallback, std::ostream& warnings)
{
  vtkDataArray* array = NumericPointArray(input, name, role, fallback, warnings);
  if (array && array->GetNumberOfComponents() != 1)
  {
    warnings << role << " array '" << name << "' has " << array->GetNumberOfComponents()
             << " components, one value per particle is needed: " << fallback << ". ";
    array = nullptr;
  }
  return array;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::WarnOnChange(const std::string& warning, std::string& lastWarning)
{
  if (!warning.empty() && warning != lastWarning)
  {
    vtkWarningMacro(<< warning);
  }
  lastWarning = warning;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::GetBufferToViewMatrix(
  vtkRenderer* ren, vtkActor* actor, vtkMatrix4x4* bufferToView)
{
  // view * actor * VBO shift/scale undone, composed in double (the shaders get it in float with
  // the translation split off, see prDepthOfSplitPointVC)
  vtkNew<vtkMatrix4x4> shiftScale;
  vtkMatrix4x4::Transpose(this->VBOShiftScale, shiftScale); // VBOShiftScale is stored transposed
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  if (!actor->GetIsIdentity())
  {
    vtkNew<vtkMatrix4x4> modelToView;
    vtkMatrix4x4::Multiply4x4(view, actor->GetMatrix(), modelToView);
    vtkMatrix4x4::Multiply4x4(modelToView, shiftScale, bufferToView);
  }
  else
  {
    vtkMatrix4x4::Multiply4x4(view, shiftScale, bufferToView);
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkParticleSphereMapper::GetParticleGeometryTime()
{
  this->PrepareParticles();
  return this->Internals->PrepareTime;
}

//------------------------------------------------------------------------------
vtkFloatArray* vtkParticleSphereMapper::GetParticleRadii()
{
  this->PrepareParticles();
  return this->Internals->Radii;
}

//------------------------------------------------------------------------------
const char* vtkParticleSphereMapper::GetLastInputWarning()
{
  return this->Internals->LastWarning.c_str();
}

//------------------------------------------------------------------------------
double vtkParticleSphereMapper::GetRadiusScaleVC(vtkActor* actor) const
{
  double scale = 1.0;
  if (actor && !actor->GetIsIdentity())
  {
    const double det = actor->GetMatrix()->Determinant();
    scale = std::cbrt(std::abs(det));
  }
  return this->RadiusScaleFactor * scale;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    vtkErrorMacro(<< "No input.");
    return;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (this->PrepareParticles() == 0)
  {
    return; // warned once in PrepareParticles
  }
  this->Superclass::RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  shaders[vtkShader::Vertex]->SetSource(vtkParticleShaders::Get("ParticleSphereVS"));
  shaders[vtkShader::Fragment]->SetSource(vtkParticleShaders::Get("ParticleSphereFS"));
  shaders[vtkShader::Geometry]->SetSource(vtkParticleShaders::Get("ParticleSphereGS"));
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  ++this->NumberOfShaderBuilds;
  this->Superclass::BuildShaders(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  // Ids for the hardware selector: the particle index, also for cell ids (the fragment stage
  // would otherwise use gl_PrimitiveID plus the offset of a polygon mapper's cell batches).
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  // (times the stride when only every k-th particle is drawn: the index of the input point)
  vtkShaderProgram::Substitute(
    fs, "gl_PrimitiveID", "(particleIdVSOutput * particleIdStride)", true);
  // A particle's colour is one value for its whole imposter: pass VTK's scalar colour flat, not
  // interpolated (interpolating a constant rounds, e.g. an alpha of 1 to 1 - 6e-8).
  vtkShaderProgram::Substitute(
    fs, "in vec4 vertexColorVSOutput;", "flat in vec4 vertexColorVSOutput;");
  shaders[vtkShader::Fragment]->SetSource(fs);
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  vtkShaderProgram::Substitute(
    vs, "out vec4 vertexColorVSOutput;", "flat out vec4 vertexColorVSOutput;");
  shaders[vtkShader::Vertex]->SetSource(vs);
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  vtkShaderProgram::Substitute(
    gs, "in vec4 vertexColorVSOutput[];", "flat in vec4 vertexColorVSOutput[];");
  vtkShaderProgram::Substitute(
    gs, "out vec4 vertexColorGSOutput;", "flat out vec4 vertexColorGSOutput;");
  // the ellipsoid variant (EllipsoidFrame.glsl), in all three stages
  if (this->Internals->Ellipsoids)
  {
    for (std::string* source : { &vs, &gs, &fs })
    {
      vtkShaderProgram::Substitute(
        *source, "//VTK::System::Dec", "//VTK::System::Dec\n#define PR_ELLIPSOID\n", false);
    }
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
  // the per-sphere occlusion test, only where the culler draws this program
  if (this->GetOcclusionCullingCompiled(ren))
  {
    vtkShaderProgram::Substitute(
      gs, "//VTK::System::Dec", "//VTK::System::Dec\n#define PR_OCCLUSION_CULLING\n", false);
  }
  shaders[vtkShader::Geometry]->SetSource(gs);
  if (this->UseClipBox)
  {
    // the clip box (SetClipBox): the box relative to each centre, in buffer coordinates
    std::string vsBox = shaders[vtkShader::Vertex]->GetSource();
    std::string gsBox = shaders[vtkShader::Geometry]->GetSource();
    std::string fsBox = shaders[vtkShader::Fragment]->GetSource();
    vtkParticleShaderHooks hooks(this);
    hooks.Begin(vsBox, gsBox, fsBox);
    hooks.Insert(vtkParticleShaderHooks::Vertex, "//PR::Sphere::Dec",
      "uniform vec3 prClipBoxLo;\nuniform vec3 prClipBoxHi;");
    hooks.AddSphereVarying("vec3", "prBoxLo");
    hooks.AddSphereVarying("vec3", "prBoxHi");
    hooks.Insert(vtkParticleShaderHooks::Vertex, "//PR::Sphere::Impl",
      "prBoxLoVSOutput = prClipBoxLo - vertexMC.xyz;\n"
      "  prBoxHiVSOutput = prClipBoxHi - vertexMC.xyz;");
    hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Sphere::Dec",
      "#define PR_CLIP_BOX\nuniform mat3 prClipBoxAxes;\n//PR::Include ClipBox");
    if (!this->GetClipBoxBySegment())
    {
      // opaque: the visible point decides
      hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Surface::Normal",
        "if (!prInsideClipBox(vertexVC.xyz - centerVC))\n"
        "  {\n"
        "    discard;\n"
        "  }");
    }
    shaders[vtkShader::Vertex]->SetSource(vsBox);
    shaders[vtkShader::Geometry]->SetSource(gsBox);
    shaders[vtkShader::Fragment]->SetSource(fsBox);
  }
  // Includes added by the replacements and render passes.
  for (auto type : { vtkShader::Vertex, vtkShader::Geometry, vtkShader::Fragment })
  {
    shaders[type]->SetSource(vtkParticleShaders::ResolveIncludes(shaders[type]->GetSource()));
  }
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // (the program is then built with the current shape: ReplaceShaderValues)
  const bool ellipsoids = this->Internals->Ellipsoids;
  auto built = this->Internals->BuiltEllipsoids.find(&cellBO);
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) ||
    built == this->Internals->BuiltEllipsoids.end() || built->second != ellipsoids;
  if (rebuild)
  {
    this->Internals->BuiltEllipsoids[&cellBO] = ellipsoids;
  }
  return rebuild;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderPositionVC(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // The templates compute the view-coordinate positions themselves.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // The normal is the ray-cast sphere normal, computed in the fragment template.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderCoincidentOffset(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // Ray-cast spheres write exact depths; coincident-topology offsets do not apply.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderDepth(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // gl_FragDepth is always written by the fragment template.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderTCoord(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // Particles have no texture coordinates.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderEdges(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
  // Particles have no edges.
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  std::string fs = shaders[vtkShader::Fragment]->GetSource();

  vtkInformation* info = actor->GetPropertyKeys();
  if (info && info->Has(vtkLightingMapPass::RENDER_NORMALS()))
  {
    vtkParticleShaders::ReplaceHook(fs, "//PR::Lighting::Impl",
      "  vec3 n = (normalVCVSOutput + 1.0) * 0.5;\n"
      "  gl_FragData[0] = vec4(n.x, n.y, n.z, 1.0);\n"
      "  prLit = false;");
    shaders[vtkShader::Fragment]->SetSource(fs);
    return;
  }

  int complexity = this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity;
  const int count = this->PrimitiveInfo[this->LastBoundBO].LastLightCount;
  if (count == 0)
  {
    complexity = 0;
  }

  vtkShaderProgram::Substitute(fs, "//VTK::Light::Dec",
    std::string(static_cast<vtkOpenGLRenderer*>(ren)->GetLightingUniforms()) +
      "\n//PR::Include Lighting\n");

  std::ostringstream impl;
  if (info && info->Has(vtkLightingMapPass::RENDER_LUMINANCE()))
  {
    impl << "  diffuseColor = vec3(1.0);\n  specularColor = vec3(1.0);\n";
  }
  if (complexity == 0)
  {
    impl << "  prSurfaceColor = ambientColor + diffuseColor;\n";
  }
  else
  {
    impl << vtkParticleSphereMapper::GetLightSumCode(complexity, count)
         << "  prSurfaceColor = ambientColor + diffuse * diffuseColor + specular * "
            "specularColor;\n";
  }
  // (the template applies ambient occlusion and writes gl_FragData[0] after this)
  vtkParticleShaders::ReplaceHook(fs, "//PR::Lighting::Impl", impl.str());
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
std::string vtkParticleSphereMapper::GetLightSumCode(int complexity, int count)
{
  std::ostringstream impl;
  impl << "  vec3 diffuse = vec3(0.0);\n"
          "  vec3 specular = vec3(0.0);\n";
  if (complexity == 0)
  {
    impl << "  diffuse = vec3(1.0);\n";
    return impl.str();
  }
  for (int i = 0; i < count; ++i)
  {
    if (complexity == 1)
    {
      impl << "  prHeadlight(normalVCVSOutput, lightColor" << i
           << ", specularPower, diffuse, specular);\n";
    }
    else if (complexity == 2)
    {
      impl << "  prSceneLight(normalVCVSOutput, vertexVC.xyz, lightColor" << i
           << ", lightDirectionVC" << i
           << ", 0, vec3(0.0), vec3(1.0, 0.0, 0.0), 180.0, 1.0, specularPower, diffuse, "
              "specular);\n";
    }
    else
    {
      impl << "  prSceneLight(normalVCVSOutput, vertexVC.xyz, lightColor" << i
           << ", lightDirectionVC" << i << ", lightPositional" << i << ", lightPositionVC" << i
           << ", lightAttenuation" << i << ", lightConeAngle" << i << ", lightExponent" << i
           << ", specularPower, diffuse, specular);\n";
    }
  }
  return impl.str();
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  // MCVCMatrix with the VBO shift/scale folded in, cameraParallel, ...
  this->Superclass::SetCameraShaderParameters(cellBO, ren, actor);

  vtkInternals& internals = *this->Internals;
  vtkShaderProgram* program = cellBO.Program;
  vtkOpenGLCamera* cam = static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera());
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  // the world -> clip matrix these uniforms were made from (stored transposed), for the occlusion
  // culler: its tests must use what the draw uses
  internals.DrawWCDC->DeepCopy(wcdc);
  program->SetUniformMatrix("VCDCMatrix", vcdc);
  vtkNew<vtkMatrix4x4> dcvc;
  vtkMatrix4x4::Invert(vcdc, dcvc);
  program->SetUniformMatrix("DCVCMatrix", dcvc);
  program->SetUniformi("cameraParallel", cam->GetParallelProjection());
  program->SetUniformf("radiusScaleVC", static_cast<float>(this->GetRadiusScaleVC(actor)));
  if (program->IsUniformUsed("particleIdStride"))
  {
    program->SetUniformi("particleIdStride", static_cast<int>(this->Internals->Stride));
  }

  // Clip-space z and w of the MC->VC translation, in double (see prDepthOfSplitPointVC). The
  // translation is that of the MCVC matrix the superclass just set (actor, camera, VBO shift).
  if (program->IsUniformUsed("clipZWOfTranslation"))
  {
    vtkNew<vtkMatrix4x4> mcvc; // row-major, points as columns
    this->GetBufferToViewMatrix(ren, actor, mcvc);
    const double t[4] = { mcvc->GetElement(0, 3), mcvc->GetElement(1, 3), mcvc->GetElement(2, 3),
      1.0 };
    // vcdc is stored transposed (column-major for OpenGL)
    double zw[2] = { 0.0, 0.0 };
    for (int k = 0; k < 4; ++k)
    {
      zw[0] += vcdc->GetElement(k, 2) * t[k];
      zw[1] += vcdc->GetElement(k, 3) * t[k];
    }
    const float clipZW[2] = { static_cast<float>(zw[0]), static_cast<float>(zw[1]) };
    program->SetUniform2f("clipZWOfTranslation", clipZW);
  }

  if (program->IsUniformUsed("axesToVC"))
  {
    this->SetEllipsoidUniforms(program, ren, actor);
  }

  if (this->UseClipBox && program->IsUniformUsed("prClipBoxAxes"))
  {
    // the box in buffer coordinates (the VBO shift/scale is a translation and an axis scale),
    // and view offsets -> buffer offsets: the inverse of the buffer -> view rotation/scale
    vtkNew<vtkMatrix4x4> bufferToModel;
    vtkMatrix4x4::Transpose(this->VBOShiftScale, bufferToModel);
    vtkNew<vtkMatrix4x4> modelToBuffer;
    vtkMatrix4x4::Invert(bufferToModel, modelToBuffer);
    float lo[3];
    float hi[3];
    for (int k = 0; k < 3; ++k)
    {
      const double a =
        modelToBuffer->GetElement(k, k) * this->ClipBox[2 * k] + modelToBuffer->GetElement(k, 3);
      const double b = modelToBuffer->GetElement(k, k) * this->ClipBox[2 * k + 1] +
        modelToBuffer->GetElement(k, 3);
      lo[k] = static_cast<float>(std::min(a, b));
      hi[k] = static_cast<float>(std::max(a, b));
    }
    program->SetUniform3f("prClipBoxLo", lo);
    program->SetUniform3f("prClipBoxHi", hi);
    vtkNew<vtkMatrix4x4> bufferToView;
    this->GetBufferToViewMatrix(ren, actor, bufferToView);
    vtkNew<vtkMatrix3x3> linear;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        linear->SetElement(i, j, bufferToView->GetElement(i, j));
      }
    }
    linear->Invert();
    // SetUniformMatrix uploads the elements in storage order, which GLSL reads column-major:
    // upload the transpose for prClipBoxAxes * v to be linear * v
    linear->Transpose();
    program->SetUniformMatrix("prClipBoxAxes", linear);
  }
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::GetAxesToViewMatrix(
  vtkRenderer* ren, vtkActor* actor, double axesToView[3][3])
{
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  vtkNew<vtkMatrix4x4> modelToView;
  if (actor && !actor->GetIsIdentity())
  {
    vtkMatrix4x4::Multiply4x4(view, actor->GetMatrix(), modelToView);
  }
  else
  {
    modelToView->DeepCopy(view);
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      axesToView[i][j] = this->RadiusScaleFactor * modelToView->GetElement(i, j);
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetEllipsoidUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor)
{
  // A = axesToVC R(q) diag(a) (EllipsoidFrame.glsl): the model -> view linear map without the
  // VBO shift/scale (axes are lengths in model units), and its inverse, both in double
  double axesToView[3][3];
  this->GetAxesToViewMatrix(ren, actor, axesToView);
  double inverse[3][3];
  vtkMath::Invert3x3(axesToView, inverse);
  // SetUniformMatrix uploads the elements in storage order, which GLSL reads column-major:
  // upload the transposes
  vtkNew<vtkMatrix3x3> forward;
  vtkNew<vtkMatrix3x3> backward;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      forward->SetElement(j, i, axesToView[i][j]);
      backward->SetElement(j, i, inverse[i][j]);
    }
  }
  program->SetUniformMatrix("axesToVC", forward);
  program->SetUniformMatrix("vcToAxes", backward);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetClipBox(const double box[6])
{
  const bool use = box && vtkMath::AreBoundsInitialized(box) && box[0] <= box[1] &&
    box[2] <= box[3] && box[4] <= box[5];
  if (use != this->UseClipBox)
  {
    this->UseClipBox = use;
    this->Modified(); // another shader variant
  }
  if (use)
  {
    std::copy(box, box + 6, this->ClipBox); // a uniform: no new shader
  }
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetEmissionAbsorptionGlyphs()
{
  return false;
}

//------------------------------------------------------------------------------
int vtkParticleSphereMapper::GetEmissionDensityModel()
{
  return vtkParticleEmissionModel::CONSTANT_DENSITY;
}

//------------------------------------------------------------------------------
double vtkParticleSphereMapper::GetEmissionHollowFraction()
{
  return 0.0;
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkParticleSphereMapper::GetEmissionOpacities()
{
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetDrawsSphereGlyphs()
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetClipBox(double box[6]) const
{
  if (!this->UseClipBox)
  {
    vtkMath::UninitializeBounds(box);
    return false;
  }
  std::copy(this->ClipBox, this->ClipBox + 6, box);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetNeedToRebuildBufferObjects(vtkRenderer*, vtkActor*)
{
  // Unlike polygons, the buffers hold nothing that depends on the actor or its property (material
  // colours are uniforms), so only the input and the mapper's data settings matter.
  const vtkMTimeType inputTime = this->CurrentInput ? this->CurrentInput->GetMTime() : 0;
  return this->VBOBuildTime < inputTime || this->VBOBuildTime < this->GetParticleDataMTime() ||
    this->VBOBuildTime < this->Internals->PrepareTime ||
    this->Internals->BuiltInput != this->CurrentInput;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  const double start = vtkTimerLog::GetUniversalTime();
  // A long upload reports its stages as progress (ProgressThreshold): validation, colour mapping
  // and the buffer build (0.15, 0.3, 1; the build is most of an upload of 10^7 particles:
  // 1.6 s on llvmpipe).
  const vtkIdType inputPoints =
    this->GetInput() && this->GetInput()->GetPoints() ? this->GetInput()->GetNumberOfPoints() : 0;
  const bool reportProgress = inputPoints >= this->ProgressThreshold;
  if (reportProgress)
  {
    const std::string text = "Uploading " + std::to_string(inputPoints) + " particles";
    this->SetProgressText(text.c_str());
    this->UpdateProgress(0.0);
  }
  const vtkIdType numPts = this->PrepareParticles();
  if (reportProgress)
  {
    this->UpdateProgress(UploadProgressValidated);
  }

  // Scalars through the lookup table, as every vtkMapper does (sets this->Colors).
  this->MapScalars(1.0);
  if (reportProgress)
  {
    this->UpdateProgress(UploadProgressColoured);
  }
  vtkUnsignedCharArray* colors = this->Colors;
  if (colors && colors->GetNumberOfTuples() != numPts)
  {
    colors = nullptr; // cell scalars do not colour particles
  }

  // More particles than the vertex buffers can hold (MaximumNumberOfParticles): every k-th.
  internals.Stride = 1;
  if (numPts > this->MaximumNumberOfParticles)
  {
    internals.Stride =
      (numPts + this->MaximumNumberOfParticles - 1) / this->MaximumNumberOfParticles;
  }
  internals.StrideArrays.clear();
  vtkIdType uploaded = numPts;
  std::string strideWarning;
  if (internals.Stride > 1)
  {
    uploaded = (numPts + internals.Stride - 1) / internals.Stride;
    std::ostringstream text;
    text << numPts << " particles exceed MaximumNumberOfParticles ("
         << this->MaximumNumberOfParticles
         << "; vertex buffers beyond 2 GiB fail or crash on common OpenGL drivers, llvmpipe "
            "among them): drawing one particle in "
         << internals.Stride << " (" << uploaded << " of " << numPts << ").";
    strideWarning = text.str();
  }
  this->WarnOnChange(strideWarning, internals.LastStrideWarning);
  internals.UploadedPositions = this->StrideForUpload(internals.Positions);
  internals.UploadedRadii = vtkFloatArray::SafeDownCast(this->StrideForUpload(internals.Radii));
  if (colors)
  {
    colors = vtkUnsignedCharArray::SafeDownCast(this->StrideForUpload(colors));
  }

  // One origin for all positions in float keeps about 2^-23 of the data's extent. When that is
  // not a thousandth of the smallest radius (a lost atom far away stretches the extent), the
  // default method switches to VTK's focal-point shift: positions relative to the camera's focal
  // point, re-uploaded when it moves (vtkOpenGLPolyDataMapper::UpdateCameraShiftScale), exact
  // where the camera looks.
  this->UpdateFocalPointShift();

  this->VBOs->CacheDataArray("vertexMC", internals.UploadedPositions, ren, VTK_FLOAT);
  vtkOpenGLVertexBufferObject* posVBO = this->VBOs->GetVBO("vertexMC");
  if (posVBO)
  {
    this->SetPositionShiftScale(posVBO);
    posVBO->SetProp3D(act);
    posVBO->SetCamera(ren->GetActiveCamera());
  }
  this->VBOs->CacheDataArray("radiusMC", internals.UploadedRadii, ren, VTK_FLOAT);
  this->VBOs->CacheDataArray("scalarColor", colors, ren, VTK_UNSIGNED_CHAR);
  // ellipsoids: semi-axes and quaternions (28 more bytes per particle); none for spheres
  internals.UploadedAxes = internals.Ellipsoids ? this->StrideForUpload(internals.Axes) : nullptr;
  internals.UploadedOrientations =
    internals.Ellipsoids ? this->StrideForUpload(internals.Orientations) : nullptr;
  this->VBOs->CacheDataArray("axesMC", internals.UploadedAxes, ren, VTK_FLOAT);
  this->VBOs->CacheDataArray("orientationMC", internals.UploadedOrientations, ren, VTK_FLOAT);
  // (for compute passes that deposit the particles' volume: GetParticleBuffers)
  internals.UploadedVolumeRadii =
    internals.Ellipsoids ? this->StrideForUpload(internals.VolumeRadii) : nullptr;
  this->VBOs->CacheDataArray("volumeRadiusMC", internals.UploadedVolumeRadii, ren, VTK_FLOAT);
  this->CacheParticleAttributes(ren, act);
  this->VBOs->BuildAllVBOs(ren);
  if (reportProgress)
  {
    this->UpdateProgress(1.0);
    this->SetProgressText(nullptr);
  }

  posVBO = this->VBOs->GetVBO("vertexMC");
  this->VBOShiftScale->Identity();
  if (posVBO && posVBO->GetCoordShiftAndScaleEnabled())
  {
    std::vector<double> const& shift = posVBO->GetShift();
    std::vector<double> const& scale = posVBO->GetScale();
    this->VBOInverseTransform->Identity();
    this->VBOInverseTransform->Translate(shift[0], shift[1], shift[2]);
    this->VBOInverseTransform->Scale(1.0 / scale[0], 1.0 / scale[1], 1.0 / scale[2]);
    this->VBOInverseTransform->GetTranspose(this->VBOShiftScale);
  }

  // No index buffers: one GL_POINTS draw of all particles. The triangle helper (the one the
  // superclass lights whatever the normals) gets the particle count as its index count, which
  // makes the superclass bind the vertex attributes to it.
  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    this->Primitives[i].IBO->IndexCount = 0;
  }
  this->Primitives[PrimitiveTris].IBO->IndexCount = static_cast<size_t>(uploaded);
  this->VBOBuildTime.Modified();
  internals.BuiltInput = this->CurrentInput;
  ++this->NumberOfUploads;
  if (this->CollectTimings)
  {
    glFinish(); // the upload is complete when the GPU has the buffers
  }
  this->LastUploadSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop)
{
  const int pass = sel->GetCurrentPass();
  vtkPolyData* poly = this->CurrentInput;
  if (!poly || !this->PopulateSelectionSettings ||
    (pass != vtkHardwareSelector::CELL_ID_LOW24 && pass != vtkHardwareSelector::CELL_ID_HIGH24))
  {
    // point ids, process ids, ...: the superclass's handling is right for particles
    this->Superclass::ProcessSelectorPixelBuffers(sel, pixeloffsets, prop);
    return;
  }

  // The shader wrote the particle index. Map it to the vertex cell holding the particle.
  vtkInternals& internals = *this->Internals;
  vtkCellArray* verts = poly->GetVerts();
  const vtkIdType numPts = poly->GetNumberOfPoints();
  if (verts && verts->GetNumberOfCells() > 0 &&
    (internals.VertexCellOfPointTime < poly->GetMTime() ||
      static_cast<vtkIdType>(internals.VertexCellOfPoint.size()) != numPts))
  {
    internals.VertexCellOfPoint.assign(numPts, -1);
    vtkIdType cellId = 0;
    auto iter = vtk::TakeSmartPointer(verts->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++cellId)
    {
      vtkIdType size;
      const vtkIdType* ids;
      iter->GetCurrentCell(size, ids);
      for (vtkIdType k = 0; k < size; ++k)
      {
        if (ids[k] >= 0 && ids[k] < numPts && internals.VertexCellOfPoint[ids[k]] < 0)
        {
          internals.VertexCellOfPoint[ids[k]] = cellId;
        }
      }
    }
    internals.VertexCellOfPointTime.Modified();
  }
  const bool mapToVerts = verts && verts->GetNumberOfCells() > 0;
  vtkIdTypeArray* cellIdArray = this->CellIdArrayName
    ? vtkArrayDownCast<vtkIdTypeArray>(poly->GetCellData()->GetArray(this->CellIdArrayName))
    : nullptr;

  unsigned char* rawLow = sel->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_LOW24);
  unsigned char* rawHigh = sel->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_HIGH24);
  unsigned char* out = sel->GetPixelBuffer(pass);
  if (!rawLow || !out)
  {
    return;
  }
  for (unsigned int pos : pixeloffsets)
  {
    vtkIdType particle = rawLow[pos] | (rawLow[pos + 1] << 8) | (rawLow[pos + 2] << 16);
    if (rawHigh)
    {
      particle |= static_cast<vtkIdType>(rawHigh[pos]) << 24;
    }
    vtkIdType id = particle;
    if (mapToVerts && particle < numPts)
    {
      id = internals.VertexCellOfPoint[particle];
      if (id >= 0 && cellIdArray && id < cellIdArray->GetNumberOfTuples())
      {
        id = cellIdArray->GetValue(id);
      }
    }
    if (pass == vtkHardwareSelector::CELL_ID_LOW24)
    {
      out[pos] = id & 0xff;
      out[pos + 1] = (id >> 8) & 0xff;
      out[pos + 2] = (id >> 16) & 0xff;
    }
    else
    {
      out[pos] = (id >> 24) & 0xff;
      out[pos + 1] = (id >> 32) & 0xff;
      out[pos + 2] = (id >> 40) & 0xff;
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor*)
{
  // The selector sizes its id passes from these maxima; the superclass derives the cell maximum
  // from index buffers, which this mapper does not have.
  vtkHardwareSelector* selector = ren->GetSelector();
  const vtkIdType count = static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount);
  const vtkIdType maxId = std::max<vtkIdType>(0, (count - 1) * this->Internals->Stride);
  selector->UpdateMaximumPointId(maxId);
  selector->UpdateMaximumCellId(maxId);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  // the triangle helper: the superclass lights triangles whatever the normals are; its index
  // count is the number of particles in the vertex buffers (see BuildBufferObjects)
  vtkOpenGLHelper& cellBO = this->Primitives[PrimitiveTris];
  const vtkIdType numPts = static_cast<vtkIdType>(cellBO.IBO->IndexCount);
  if (numPts <= 0)
  {
    return;
  }
  this->UpdateShaders(cellBO, ren, actor);
  if (!cellBO.Program)
  {
    return;
  }
  if (this->CollectTimings)
  {
    this->Internals->DrawTimer.Reset();
    this->Internals->DrawTimer.Start();
  }
  vtkInternals& internals = *this->Internals;
  if (this->OcclusionCulling && numPts >= this->OcclusionCullingThreshold && !ren->GetSelector())
  {
    vtkParticleOcclusionCuller* culler = internals.Culler;
    if (internals.CullerBuildTime < this->VBOBuildTime)
    {
      culler->Build(ren, internals.UploadedPositions, this->GetCullingRadii(), numPts);
      internals.CullerBuildTime.Modified();
    }
    culler->Draw(ren, cellBO.Program, internals.DrawWCDC,
      actor->GetIsIdentity() ? nullptr : actor->GetMatrix(), this->GetRadiusScaleVC(actor));
  }
  else
  {
    internals.Culler->DrawAll(ren, cellBO.Program, numPts);
  }
  if (this->CollectTimings)
  {
    internals.DrawTimer.Stop();
  }
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::SetPositionShiftScale(vtkOpenGLVertexBufferObject* positions)
{
  using VBO = vtkOpenGLVertexBufferObject;
  const double* b = this->PositionBounds;
  const bool automatic =
    this->ShiftScaleMethod == VBO::AUTO_SHIFT_SCALE || this->ShiftScaleMethod == VBO::AUTO_SHIFT;
  if (!automatic || !vtkMath::AreBoundsInitialized(b))
  {
    positions->SetCoordShiftAndScaleMethod(
      static_cast<VBO::ShiftScaleMethod>(this->ShiftScaleMethod));
    return;
  }
  // VTK's automatic shift and scale (vtkOpenGLVertexBufferObject::UpdateShiftScale), from the
  // given bounds instead of the uploaded array's range: the same operations, so that one piece
  // holding all the data uploads what AUTO_SHIFT_SCALE would
  double diag2 = 0.0;
  double dist2 = 0.0;
  double shift[3];
  double scale[3];
  for (int k = 0; k < 3; ++k)
  {
    const double delta = b[2 * k + 1] - b[2 * k];
    diag2 += delta * delta;
    shift[k] = 0.5 * (b[2 * k + 1] + b[2 * k]);
    dist2 += shift[k] * shift[k];
    scale[k] = delta > 0 ? 1.0 / delta : 1.0;
  }
  bool shifted = true;
  if (this->ShiftScaleMethod == VBO::AUTO_SHIFT_SCALE)
  {
    shifted =
      (diag2 > 0 && (std::abs(dist2) / diag2 > 1.0e6 || std::abs(std::log10(diag2)) > 3.0)) ||
      (diag2 == 0 && dist2 > 1.0e6);
  }
  else
  {
    std::fill(scale, scale + 3, 1.0); // AUTO_SHIFT: the translation only
  }
  if (!shifted)
  {
    std::fill(shift, shift + 3, 0.0);
    std::fill(scale, scale + 3, 1.0);
  }
  positions->SetCoordShiftAndScaleMethod(VBO::MANUAL_SHIFT_SCALE);
  positions->SetShift(shift[0], shift[1], shift[2]);
  positions->SetScale(scale[0], scale[1], scale[2]);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::UpdateFocalPointShift()
{
  vtkInternals& internals = *this->Internals;
  const double* b = vtkMath::AreBoundsInitialized(this->PositionBounds) ? this->PositionBounds
                                                                        : internals.CenterBounds;
  double extent = 0.0;
  if (b[0] <= b[1])
  {
    extent = std::max(b[1] - b[0], std::max(b[3] - b[2], b[5] - b[4]));
  }
  const double step = extent * std::ldexp(1.0, -23); // float spacing across the extent
  // (not with thinned data: VTK's camera-shift update reads the input's own points)
  const bool needed =
    internals.MinRadius > 0.0 && step > 1e-3 * internals.MinRadius && internals.Stride == 1;
  if (internals.CentreShift)
  {
    this->ShiftScaleMethod = vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE; // decided again below
    internals.CentreShift = false;
  }
  std::string warning;
  if (needed &&
    (this->ShiftScaleMethod == vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE ||
      internals.FocalPointShift))
  {
    // (set directly: the mapper's modification would re-upload every frame)
    this->ShiftScaleMethod = vtkOpenGLVertexBufferObject::FOCAL_POINT_SHIFT_SCALE;
    internals.FocalPointShift = true;
    std::ostringstream text;
    text << "The particles span " << extent << ", " << extent / internals.MinRadius
         << " times the smallest radius: beyond single precision with one origin. Positions are "
            "uploaded relative to the camera's focal point (re-uploaded when it moves), exact "
            "near it; far from the focal point they keep about "
         << step << " units.";
    warning = text.str();
  }
  else if (!needed && internals.FocalPointShift)
  {
    this->ShiftScaleMethod = vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE;
    internals.FocalPointShift = false;
  }
  this->WarnOnChange(warning, internals.LastShiftWarning);

  // Particles of small extent away from the origin (one particle, a tight cluster): VTK's
  // AUTO_SHIFT_SCALE keeps their coordinates (it shifts a single point only beyond 1e3 from the
  // origin), and the float view translation then resolves 2^-23 of their distance from the
  // origin (measured: radius 1e-6 at (1, 2, 3), depth off by 0.48 R). Uploaded relative to the
  // centre of their bounds instead, the translation is formed in double.
  double centre = 0.0;
  if (b[0] <= b[1])
  {
    for (int k = 0; k < 3; ++k)
    {
      centre = std::max(centre, std::abs(0.5 * (b[2 * k] + b[2 * k + 1])));
    }
  }
  const bool centred = !internals.FocalPointShift && internals.MinRadius > 0.0 &&
    centre * std::ldexp(1.0, -23) > 1e-3 * internals.MinRadius;
  if (centred && this->ShiftScaleMethod == vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE)
  {
    this->ShiftScaleMethod = vtkOpenGLVertexBufferObject::AUTO_SHIFT;
    internals.CentreShift = true;
  }

  // What no origin fixes: VTK composes the camera and actor matrices in double, which resolves
  // 2^-52 of the largest coordinate (measured from outside: 1.6 % of a radius of 1e-6 at 1e8, an
  // edge pixel off by 160/255). Supported: that step within 1e-3 of the smallest radius, i.e.
  // the largest coordinate up to about 4.5e12 smallest radii.
  double largest = 0.0;
  if (b[0] <= b[1])
  {
    for (int k = 0; k < 6; ++k)
    {
      largest = std::max(largest, std::abs(b[k]));
    }
  }
  const double doubleStep = largest * std::ldexp(1.0, -52);
  const double smallest = internals.MinRadius * std::abs(this->RadiusScaleFactor);
  std::string precision;
  if (smallest > 0.0 && doubleStep > 1e-3 * smallest)
  {
    std::ostringstream text;
    text << "The particles lie up to " << largest << " from the origin with radii down to "
         << smallest << " (" << largest / smallest
         << " radii): beyond double precision for VTK's camera and actor matrices, which resolve "
         << doubleStep << " there, " << 100.0 * doubleStep / smallest
         << " % of the smallest radius, so the smallest spheres' edges can be off by that much. "
            "Supported: up to about 4.5e12 radii from the origin. Translate the data towards the "
            "origin (e.g. with a Transform filter) to draw them exactly.";
    precision = text.str();
  }
  this->WarnOnChange(precision, internals.LastPrecisionWarning);
}

//------------------------------------------------------------------------------
vtkDataArray* vtkParticleSphereMapper::StrideForUpload(vtkDataArray* array)
{
  vtkInternals& internals = *this->Internals;
  const vtkIdType stride = internals.Stride;
  if (!array || stride <= 1)
  {
    return array;
  }
  const vtkIdType n = array->GetNumberOfTuples();
  const vtkIdType m = (n + stride - 1) / stride;
  const int components = array->GetNumberOfComponents();
  // (the same value type in VTK's plain layout: a new instance of an implicit input array would
  // be implicit too, and not writable)
  vtkSmartPointer<vtkDataArray> subset =
    vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(array->GetDataType()));
  subset->SetNumberOfComponents(components);
  subset->SetNumberOfTuples(m);
  subset->SetName(array->GetName());
  // every stride-th tuple, in the arrays' own value type (any memory layout)
  auto strideCopy = [&](auto* from, auto* to)
  {
    const auto in = vtk::DataArrayValueRange(from);
    auto out = vtk::DataArrayValueRange(to);
    vtkSMPTools::For(0, m,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int c = 0; c < components; ++c)
          {
            out[i * components + c] = in[i * stride * components + c];
          }
        }
      });
  };
  if (!vtkArrayDispatch::Dispatch2SameValueType::Execute(array, subset.Get(), strideCopy))
  {
    strideCopy(array, subset.Get()); // an array outside the dispatch list (implicit, or another
                                     // value type): through double
  }
  internals.StrideArrays.push_back(subset);
  return subset;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkParticleSphereMapper::GetUploadedPositions()
{
  return this->Internals->UploadedPositions;
}

//------------------------------------------------------------------------------
vtkFloatArray* vtkParticleSphereMapper::GetUploadedRadii()
{
  return this->Internals->UploadedRadii;
}

//------------------------------------------------------------------------------
const float* vtkParticleSphereMapper::GetCullingRadii()
{
  vtkFloatArray* radii = this->Internals->UploadedRadii;
  return radii ? radii->GetPointer(0) : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkParticleSphereMapper::GetParticleStride()
{
  return this->Internals->Stride;
}

//------------------------------------------------------------------------------
bool vtkParticleSphereMapper::GetOcclusionCullingCompiled(vtkRenderer* ren)
{
  return this->OcclusionCulling && !ren->GetSelector() &&
    static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount) >=
    this->OcclusionCullingThreshold;
}

//------------------------------------------------------------------------------
vtkParticleOcclusionCuller* vtkParticleSphereMapper::GetOcclusionCuller()
{
  return this->Internals->Culler;
}

//------------------------------------------------------------------------------
double vtkParticleSphereMapper::GetLastDrawGPUSeconds()
{
  vtkOpenGLRenderTimer& timer = this->Internals->DrawTimer;
  if (!timer.Stopped())
  {
    return 0.0;
  }
  return timer.GetElapsedSeconds();
}

//------------------------------------------------------------------------------
vtkParticleFrameBudget* vtkParticleSphereMapper::GetFrameBudget()
{
  return this->Internals->FrameBudget;
}

//------------------------------------------------------------------------------
std::string vtkParticleSphereMapper::GetQualityText()
{
  return this->Internals->FrameBudget->GetLastChoiceText(this->GetQualityLevelNames());
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->DrawTimer.ReleaseGraphicsResources();
  this->Internals->FrameBudget->ReleaseGraphicsResources(window);
  this->Internals->Culler->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkParticleSphereMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiusArrayName: " << (this->RadiusArrayName ? this->RadiusArrayName : "(none)")
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Shape: " << (this->Shape == ELLIPSOID ? "Ellipsoid" : "Sphere") << "\n";
  os << indent << "AxesArrayName: " << (this->AxesArrayName ? this->AxesArrayName : "(none)")
     << "\n";
  os << indent << "AxesArrayComponent: " << this->AxesArrayComponent << "\n";
  os << indent << "AxesAreDiameters: " << this->AxesAreDiameters << "\n";
  os << indent << "OrientationArrayName: "
     << (this->OrientationArrayName ? this->OrientationArrayName : "(none)") << "\n";
  os << indent << "OrientationArrayComponent: " << this->OrientationArrayComponent << "\n";
  os << indent << "TensorArrayName: " << (this->TensorArrayName ? this->TensorArrayName : "(none)")
     << "\n";
  os << indent << "RadiusScaleFactor: " << this->RadiusScaleFactor << "\n";
  os << indent << "NumberOfSkippedParticles: " << this->NumberOfSkippedParticles << "\n";
  os << indent << "CollectTimings: " << this->CollectTimings << "\n";
  os << indent << "MaximumNumberOfParticles: " << this->MaximumNumberOfParticles << "\n";
  os << indent << "OcclusionCulling: " << this->OcclusionCulling << "\n";
  os << indent << "OcclusionCullingThreshold: " << this->OcclusionCullingThreshold << "\n";
  os << indent << "PositionBounds: (" << this->PositionBounds[0] << ", " << this->PositionBounds[1]
     << ", " << this->PositionBounds[2] << ", " << this->PositionBounds[3] << ", "
     << this->PositionBounds[4] << ", " << this->PositionBounds[5] << ")\n";
  os << indent << "NumberOfUploads: " << this->NumberOfUploads << "\n";
  os << indent << "FrameBudget:\n";
  this->Internals->FrameBudget->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ClipBox: ";
  if (this->UseClipBox)
  {
    os << this->ClipBox[0] << " " << this->ClipBox[1] << " " << this->ClipBox[2] << " "
       << this->ClipBox[3] << " " << this->ClipBox[4] << " " << this->ClipBox[5] << "\n";
  }
  else
  {
    os << "(none)\n";
  }
}
