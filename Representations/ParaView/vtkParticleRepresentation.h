/**
 * @class   vtkParticleRepresentation
 * @brief   ParaView representation drawing every point of a dataset as a ray-cast sphere
 *
 * vtkParticleRepresentation is the "Particles" entry of the Representation drop-down (registered
 * as the subproxy "ParticleRepresentation" of ParaView's Geometry, UnstructuredGrid, UniformGrid
 * and StructuredGrid representations, see Plugin/ParticleRendering.xml). It works in any render
 * view (vtkPVRenderView and subclasses such as vtkParticleRenderView) and draws with a
 * vtkParticleSphereMapper and a vtkActor.
 *
 * Input: any vtkDataSet or composite dataset (multiblock, partitioned dataset (collection)).
 * Cells are ignored: the points of all non-empty leaves and their point arrays become one
 * vtkPolyData of particles (RequestData). A single leaf with explicit points shares its points
 * and point arrays (no copy); several leaves are appended (vtkAppendPolyData keeps the point
 * arrays common to all leaves); implicit points (image data, rectilinear grids) are made
 * explicit.
 *
 * Distributed rendering (more than one process; all of it collective, in the pipeline, never
 * in a render pass): translucent spheres are partitioned in RequestData
 * (vtkParticleDistributedPartition, with vtkParticlePartition: one k-d box per process, raw
 * point arrays moved, ghost copies of spheres reaching into other boxes); the view gets the
 * process's box as its geometry bounds with USE_BOUNDS_FOR_REDISTRIBUTION (IceT orders the
 * processes by the boxes; never DATA_IS_REDISTRIBUTABLE, whose appended-XML path Debian's expat
 * breaks in VTK 9.2), and the mapper clips its drawing to the box
 * (vtkParticleSphereMapper::SetClipBox), so the processes' images composite to the single-process
 * picture. The column-opacity layer estimate is taken over all processes. With the Particle Render
 * View's density-volume or voxel-cone AO, REQUEST_RENDER tells the view what the representation
 * draws, and the view (when every process renders) builds the AO volume of all processes'
 * particles of all its Particles representations and puts it on their actors
 * (vtkParticleDistributedVolumes).
 * Opaque spheres stay where they are, but in a Particle Render View that composites in order
 * (some representation is translucent) the view partitions all its Particles representations,
 * opaque ones too, into one set of boxes (vtkParticleViewPartition; the representation adds
 * itself in AddToView) and they deliver again (RequestData then only delivers). Every process (one
 * included) gives the mapper the bounds of all processes' centres
 * (vtkParticleSphereMapper::SetPositionBounds), so that the positions round to float as in one
 * process. Metaballs are opaque: Opacity and the opacity array apply to spheres only (the actor's
 * opacity is 1 for metaballs, with a warning).
 *
 * View protocol (like vtkPointGaussianRepresentation): REQUEST_UPDATE hands the particle
 * polydata to the view (vtkPVView::SetPiece), reports the bounds of the spheres (the points'
 * finite bounds grown by the largest radius in use times RadiusScaleFactor, under the actor's
 * transform, or the partition box) and the ordered-compositing needs (only when translucent);
 * REQUEST_RENDER gives the delivered piece to the mapper and updates the colouring. An empty
 * local piece (normal in parallel, or for an empty filter output) hides the actor for that
 * render instead of letting the mapper warn about an input without points.
 *
 * Radii: UseRadiusArray chooses between the point array RadiusArray and the constant Radius;
 * both are scaled by RadiusScaleFactor (map to vtkParticleSphereMapper's RadiusArrayName, Radius
 * and RadiusScaleFactor). Missing, non-numeric or multi-component radius arrays fall back to the
 * constant Radius with a warning from the mapper.
 *
 * Shape: SHAPE_SPHERE, SHAPE_ELLIPSOID (oriented ellipsoids from AxesArray and OrientationArray,
 * components picked with AxesArrayComponent and OrientationArrayComponent, diameters halved with
 * AxesAreDiameters: vtkParticleSphereMapper's Shape ELLIPSOID), SHAPE_TENSOR_ELLIPSOID (the
 * eigen-decomposition of the 9-component TensorArray, as ParaView's Tensor Glyph: the mapper's
 * TensorArrayName) or SHAPE_AUTOMATIC (the default):
 * ellipsoids when the data has the point arrays vtkLAMMPSDumpReader writes for LAMMPS's
 * ellipsoids, "semi_axes" (3 components) and, if present, "orientation" (4), spheres otherwise.
 * With ellipsoids the radius settings are not used: bounds, partitions and ghosts take each
 * particle's largest semi-axis (the point array "ParticleBoundingRadius" the representation adds
 * to its copy of the data).
 *
 * Colouring: the standard ColorArrayName (SetInputArrayToProcess), LookupTable and MapScalars;
 * point arrays only (a cell array gives the solid DiffuseColor, as in Point Gaussian).
 * Material: the actor's property (Ambient, Diffuse, Specular, SpecularPower and colours,
 * Opacity; metaballs are opaque). Transform: Position, Scale, Orientation, Origin, UserTransform.
 *
 * @sa vtkParticleSphereMapper vtkParticleRenderView vtkPointGaussianRepresentation
 */
#ifndef vtkParticleRepresentation_h
#define vtkParticleRepresentation_h

#include "vtkNew.h" // for vtkNew
#include "vtkPVDataRepresentation.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"                    // for vtkSmartPointer

#include <string> // for std::string

class vtkActor;
class vtkDataArray;
class vtkDataObject;
class vtkDoubleArray;
class vtkParticleDistributedPartition;
class vtkParticleSphereMapper;
class vtkTransparentSphereMapper;
class vtkPolyData;
class vtkScalarsToColors;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkParticleRepresentation* New();
  vtkTypeMacro(vtkParticleRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  void SetVisibility(bool val) override;

  ///@{
  /**
   * Radius source. UseRadiusArray RADIUS_ARRAY_OFF: every particle has the constant Radius;
   * RADIUS_ARRAY_ON: the point array RadiusArray gives the radii; RADIUS_ARRAY_AUTOMATIC (the
   * default): the input's one-component numeric point array named "radius" when it has one
   * (what vtkLAMMPSDumpReader and most particle codes write), otherwise the constant Radius.
   * SelectRadiusArray has the signature of SetInputArrayToProcess so ParaView's array widgets
   * can drive it; only the name is used.
   */
  enum RadiusArrayModes
  {
    RADIUS_ARRAY_OFF = 0,
    RADIUS_ARRAY_ON = 1,
    RADIUS_ARRAY_AUTOMATIC = 2
  };
  void SetUseRadiusArray(int mode);
  vtkGetMacro(UseRadiusArray, int);
  void SetRadiusArray(const char* name);
  const char* GetRadiusArray() const { return this->RadiusArray.c_str(); }
  void SelectRadiusArray(int, int, int, int, const char* name);
  void SetRadius(double radius);
  double GetRadius();
  void SetRadiusScaleFactor(double factor);
  double GetRadiusScaleFactor();
  ///@}

  ///@{
  /**
   * Particle shape (see the class description). The array selectors have the signature of
   * SetInputArrayToProcess so ParaView's array widgets can drive them; only the name is used.
   */
  enum ShapeModes
  {
    SHAPE_SPHERE = 0,
    SHAPE_ELLIPSOID = 1,
    SHAPE_AUTOMATIC = 2,
    SHAPE_TENSOR_ELLIPSOID = 3
  };
  void SetShape(int shape);
  vtkGetMacro(Shape, int);
  void SelectAxesArray(int, int, int, int, const char* name);
  void SetAxesArrayComponent(int component);
  void SetAxesAreDiameters(bool diameters);
  void SelectOrientationArray(int, int, int, int, const char* name);
  void SetOrientationArrayComponent(int component);
  void SelectTensorArray(int, int, int, int, const char* name);
  /**
   * Whether the particles are drawn as ellipsoids (the Shape in effect for the processed data).
   */
  bool GetDrawsEllipsoids();
  ///@}

  ///@{
  /**
   * Transparency (vtkTransparentSphereMapper): density model, hollow fraction, surface/volume
   * mix (alpha_RV), early termination, overlap compositing and its memory, and the maximum opacity
   * per particle from a point array mapped through OpacityArrayRange (UseOpacityArray) --
   * multiplied by Opacity.
   */
  void SetDensityModel(int model);
  void SetHollowFraction(double fraction);
  void SetVolumeMix(double mix);
  void SetEarlyTermination(int on);
  void SetOverlapCompositing(int mode); // vtkTransparentSphereMapper::OverlapCompositingModes
  // the mapper's speed/accuracy trade (vtkParticleFrameBudget::Qualities) and its last choice
  void SetInteractiveQuality(int quality);
  const char* GetQualityText();
  void SetFragmentListMemory(double mebibytes);
  void SetOverlapTolerance(double tolerance);
  void SetAutomaticErrorTolerance(double tolerance); // 1/255
  void SetAutomaticPixelShare(double share);
  void SetOpacityReference(int reference); // vtkTransparentSphereMapper::OpacityReferences
  void SetUseOpacityArray(bool use);
  vtkGetMacro(UseOpacityArray, bool);
  void SetOpacityArray(const char* name);
  const char* GetOpacityArray() const { return this->OpacityArray.c_str(); }
  void SelectOpacityArray(int, int, int, int, const char* name);
  void SetOpacityArrayRange(double lo, double hi);
  ///@}

  ///@{
  /**
   * Metaballs (vtkMetaballMapper; used with the METABALLS technique): influence factor k,
   * iso-value, search tolerance, refinement steps, iteration limit, neighbour list bound
   * (vicinity method); the method; tolerance, pass limit and time budget of the walking depth
   * plane.
   */
  void SetInfluenceFactor(double factor);
  void SetIsoValue(double value);
  void SetMetaballTolerance(double tolerance);
  void SetRefinementSteps(int steps);
  void SetIterationLimit(int limit);
  void SetMaximumNumberOfNeighbors(int count);
  void SetMetaballMethod(int method);
  void SetWalkingTolerance(double tolerance);
  void SetMaximumPasses(int passes);
  void SetTimeBudget(double seconds);
  ///@}

  ///@{
  /**
   * Which values of the opacity array map to opacity 0 and 1: OPACITY_RANGE_DATA (default) the
   * finite range of the chosen array in the current data (all processes), so that it follows
   * the array and the time step; OPACITY_RANGE_CUSTOM the OpacityArrayRange values (e.g. to keep
   * one mapping over an animation). GetOpacityArrayDataRange gives the data range (for an
   * information property: the values to start a custom range from).
   */
  enum OpacityRangeModes
  {
    OPACITY_RANGE_DATA = 0,
    OPACITY_RANGE_CUSTOM = 1
  };
  void SetOpacityArrayRangeMode(int mode);
  vtkGetMacro(OpacityArrayRangeMode, int);
  vtkGetVector2Macro(OpacityArrayDataRange, double);
  ///@}

  ///@{
  /**
   * Colour mapping, forwarded to the mapper.
   */
  void SetLookupTable(vtkScalarsToColors* lut);
  void SetMapScalars(int val);
  ///@}

  ///@{
  /**
   * Forwarded to the actor.
   */
  void SetOrientation(double x, double y, double z);
  void SetOrigin(double x, double y, double z);
  void SetPosition(double x, double y, double z);
  void SetScale(double x, double y, double z);
  void SetPickable(int val);
  void SetUserTransform(const double matrix[16]);
  ///@}

  ///@{
  /**
   * Forwarded to the actor's property.
   */
  void SetAmbient(double val);
  void SetDiffuse(double val);
  void SetSpecular(double val);
  void SetSpecularPower(double val);
  void SetAmbientColor(double r, double g, double b);
  void SetDiffuseColor(double r, double g, double b);
  void SetSpecularColor(double r, double g, double b);
  void SetOpacity(double val);
  ///@}

  ///@{
  /**
   * The drawing technique, i.e. which mapper draws the particles. Every technique's mapper is a
   * vtkParticleSphereMapper (same input handling, radii, colours); NewMapper() is the one place
   * that maps a technique to its mapper, and switching re-applies every setting the
   * representation holds. SPHERES: vtkTransparentSphereMapper, which draws opaque spheres as
   * its superclass does and translucent ones exactly (Staib et al. 2015). METABALLS:
   * vtkMetaballMapper (Mueller et al. 2007), the "Metaballs" entry of the Representation
   * drop-down (the same proxy with Technique 1, see Plugin/ParticleRendering.xml).
   */
  enum ParticleTechniques
  {
    SPHERES = 0,
    METABALLS = 1
  };
  void SetTechnique(int technique);
  vtkGetMacro(Technique, int);
  ///@}

  /**
   * The mapper and actor, for passes of vtkParticleRenderView and for tests.
   */
  vtkParticleSphereMapper* GetMapper();
  vtkActor* GetActor();

  /**
   * Number of particles of the (local) processed input, before delivery.
   */
  vtkIdType GetNumberOfParticles();

  /**
   * How the particles are spread over the processes, 5 values per process: particles of the
   * process's piece, particles it owns and ghost copies it draws after the partition, bytes it
   * sent, seconds the partition took (see vtkParticlePartition). Translucent spheres are
   * partitioned when there is more than one process; otherwise every process owns its piece. For an
   * information property.
   */
  vtkDoubleArray* GetParticleDistribution();

  /**
   * The mapper's warning about the local input ("" when it is fine), for an information
   * property: lets scripts and tests see which representation warned about what.
   */
  const char* GetParticleInputWarning();

protected:
  vtkParticleRepresentation();
  ~vtkParticleRepresentation() override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The points of every leaf of `input` with their point arrays as one vtkPolyData. Never null.
   */
  static vtkSmartPointer<vtkPolyData> MakeParticles(vtkDataObject* input, bool vertexCells);

  /**
   * Bounds of the spheres of `particles` with the current radius settings (uninitialized when
   * there is no valid point).
   */
  void ComputeSphereBounds(vtkPolyData* particles, double bounds[6]);
  // the bounds of the finite centres, cached for this points array and time
  double CenterBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  vtkDataArray* CenterBoundsArray = nullptr;
  vtkMTimeType CenterBoundsTime = 0;

  void UpdateColoringParameters();

  // spheres with Opacity below 1 or an opacity array
  bool IsTranslucent();
  // the actor's opacity: Opacity for spheres, 1 for metaballs (opaque)
  void ApplyOpacity();
  // a warning, once per change, when metaballs would have been translucent
  void WarnOpaqueMetaballs();
  // the centre bounds of all processes' particles, to the mapper (RequestData, collective)
  void UpdatePositionBounds();
  double PositionBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  // distributed rendering: the partition, the spread over the processes and the column layers
  // of all processes (RequestData), the pieces to deliver and draw
  vtkNew<vtkParticleDistributedPartition> DistributedPartition;
  // the AO volumes of all processes' particles (distributed rendering, REQUEST_RENDER)
  void UpdateMapperRadiusArray();
  // The radius array the mode selects for these particles ("" = the constant radius).
  std::string EffectiveRadiusArray(vtkPolyData* particles) const;
  void UpdateMapperOpacityArray();

  // the mapper of a technique (the one switch), and the representation's settings applied to it
  static vtkSmartPointer<vtkParticleSphereMapper> NewMapper(int technique);
  void ApplyMapperSettings();

  int Technique = SPHERES;
  vtkSmartPointer<vtkParticleSphereMapper> Mapper;
  vtkNew<vtkActor> Actor;
  // settings of the translucent techniques (vtkTransparentSphereMapper), kept for re-application
  int DensityModel = 0;
  double HollowFraction = 0.0;
  double VolumeMix = 0.0;
  bool EarlyTermination = false;
  int OverlapCompositing = 0;
  int InteractiveQuality = 0;
  double AutomaticErrorTolerance = 2.0;
  double AutomaticPixelShare = 1.0e-4;
  std::string QualityText;
  double FragmentListMemory = 256.0;
  double OverlapTolerance = 0.25;
  // settings of the metaball technique (vtkMetaballMapper's defaults)
  double InfluenceFactor = 2.0;
  double IsoValue = 1.0;
  double MetaballTolerance = 0.01;
  int RefinementSteps = 6;
  int IterationLimit = 100;
  int MaximumNumberOfNeighbors = 64;
  int MetaballMethod = 0;
  double WalkingTolerance = 1e-3;
  int MaximumPasses = 1000;
  double TimeBudget = 1.0;
  int OpacityReference = 0;
  bool HasLocalParticles = false; // the delivered local piece has points
  bool UseOpacityArray = false;
  double Opacity = 1.0;       // the Opacity property (the actor's opacity: ApplyOpacity)
  std::string OpacityWarning; // the last WarnOpaqueMetaballs warning
  int OpacityArrayRangeMode = OPACITY_RANGE_DATA;
  double OpacityArrayRange[2] = { 0.0, 1.0 };
  double OpacityArrayDataRange[2] = { 0.0, 1.0 };
  // the data range of the opacity array in the processed data, reduced over all processes
  void UpdateOpacityArrayDataRange();
  std::string OpacityArray;
  vtkSmartPointer<vtkPolyData> ProcessedData;
  // the delivered piece when it had to be flattened again on the rendering side
  vtkSmartPointer<vtkPolyData> RenderedData;
  vtkDataObject* LastDelivered = nullptr;
  vtkMTimeType LastDeliveredTime = 0;

  int UseRadiusArray = RADIUS_ARRAY_AUTOMATIC;
  std::string RadiusArray;

  // particle shape (SetShape): the settings, whether the processed data is drawn as ellipsoids,
  // and the arrays in effect
  int Shape = SHAPE_AUTOMATIC;
  std::string AxesArray = "semi_axes";
  int AxesArrayComponent = 0;
  bool AxesAreDiameters = false;
  std::string OrientationArray = "orientation";
  int OrientationArrayComponent = 0;
  std::string TensorArray;
  bool EllipsoidsInEffect(vtkPolyData* particles) const;
  // the axes and orientation arrays in effect for particles (AUTOMATIC: the reader's names)
  void EffectiveEllipsoidArrays(vtkPolyData* particles, std::string& axes, int& axesComponent,
    bool& diameters, std::string& orientation, int& orientationComponent) const;
  // the largest semi-axis of every particle as the point array "ParticleBoundingRadius" of
  // particles (ellipsoids in effect), for bounds, partitions and ghosts
  void AddBoundingRadii(vtkPolyData* particles);
  void AddTensorBoundingRadii(vtkPolyData* particles);
  void UpdateMapperShape();
  // a shape setting changes: the mapper's shape follows, the bounds and partitions are redone
  template <class T>
  void ChangeShapeSetting(T& setting, const T& value)
  {
    if (setting != value)
    {
      setting = value;
      this->UpdateMapperShape();
      this->MarkModified();
    }
  }

private:
  vtkParticleRepresentation(const vtkParticleRepresentation&) = delete;
  void operator=(const vtkParticleRepresentation&) = delete;

  // the mapper's progress (upload, depth sort) as this representation's, for ParaView
  void ForwardMapperProgress(vtkObject*, unsigned long, void* callData);
};

#endif
