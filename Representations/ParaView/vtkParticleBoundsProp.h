/**
 * @class   vtkParticleBoundsProp
 * @brief   an actor without a mapper that draws nothing and reports given bounds
 *
 * IceT (ParaView's distributed compositing) calls a process's draw callback only when the
 * bounds of the process's visible props project into the view. A pass that composites across
 * the processes while they draw (vtkPointAOPass, vtkSNDFRenderPass with a controller) needs every
 * process to draw whenever one does. vtkParticleRenderView therefore adds this prop, with the
 * view's bounds over all processes (the same on each), while such a pass is on: every process then
 * has the same bounds, and IceT draws on all of them or on none. It is a vtkActor (without a
 * mapper, so it draws nothing) because passes treat props that are not actors as foreign geometry
 * (PointAO then ignores the G-buffer's normals).
 *
 * @sa vtkParticleRenderView vtkPointAOPass
 */
#ifndef vtkParticleBoundsProp_h
#define vtkParticleBoundsProp_h

#include "vtkActor.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleBoundsProp : public vtkActor
{
public:
  static vtkParticleBoundsProp* New();
  vtkTypeMacro(vtkParticleBoundsProp, vtkActor);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The bounds reported (xmin, xmax, ymin, ymax, zmin, zmax). Default uninitialized (the
   * renderer then ignores the prop).
   */
  vtkSetVector6Macro(Bounds, double);
  double* GetBounds() VTK_SIZEHINT(6) override { return this->Bounds; }
  using vtkActor::GetBounds;
  ///@}

protected:
  vtkParticleBoundsProp();
  ~vtkParticleBoundsProp() override = default;

  double Bounds[6];

private:
  vtkParticleBoundsProp(const vtkParticleBoundsProp&) = delete;
  void operator=(const vtkParticleBoundsProp&) = delete;
};

#endif
