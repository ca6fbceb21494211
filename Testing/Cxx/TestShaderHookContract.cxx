// The shader-hook contract (vtkParticleShaderHooks) from outside the module: a throw-away pass
// written here, vtkTintByIdPass, darkens every odd particle to half through the hooks alone --
// in PreReplaceShaderValues (so the hooks must be in the templates before the mapper has filled
// VTK's tags), with a per-sphere value computed in the vertex stage from particleIdVSOutput and
// carried to the fragment stage (AddSphereVarying), applied as ambient occlusion. Checked:
// 1. odd particles are 0.5 (+-0.02) as bright as even ones, even ones as without the pass;
// 2. with vtkDensityVolumeAOPass as well, the occlusions compose: every particle's centre is
//    (tint) x (its brightness with density AO alone), within 2/255 -- neither source wins;
// 3. the same with the transparent mapper (its own hooks in the same stages);
// 4. a hook that does not exist warns exactly once, over several shader builds, naming the hook;
//    the picture is then the one without the pass's code.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Tints odd particles by Factor through the //PR:: hooks (or, with a Hook set, asks for that
// hook, to test the warning).
class vtkTintByIdPass : public vtkImageProcessingPass
{
public:
  static vtkTintByIdPass* New();
  vtkTypeMacro(vtkTintByIdPass, vtkImageProcessingPass);

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    this->PreRender(s); // registers this pass with the props' shaders
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    this->PostRender(s);
  }

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*) override
  {
    if (!vtkParticleSphereMapper::SafeDownCast(mapper))
    {
      return true;
    }
    using Hooks = vtkParticleShaderHooks;
    this->Hooks.Begin(vertexShader, geometryShader, fragmentShader);
    this->Hooks.AddSphereVarying("float", "prTint");
    this->Hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
      "prTintVSOutput = (particleIdVSOutput % 2 == 1) ? " + std::to_string(this->Factor) +
        " : 1.0;");
    this->Hooks.Insert(Hooks::Fragment, this->Hook, "prAmbientOcclusion *= prTintVSOutput;");
    ++this->Builds;
    return true;
  }

  vtkMTimeType GetShaderStageMTime() override { return this->GetMTime(); }

  double Factor = 0.5;
  std::string Hook = "//PR::AmbientOcclusion::Impl";
  int Builds = 0;

protected:
  vtkTintByIdPass() = default;
  ~vtkTintByIdPass() override = default;
  vtkParticleShaderHooks Hooks{ this };
};
vtkStandardNewMacro(vtkTintByIdPass);

// Six particles in a row, 0..5, seen from the front; lit by the headlight (ambient 0.2)
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkTintByIdPass> Tint;
  vtkNew<vtkDensityVolumeAOPass> AO;
  vtkNew<vtkActor> Actor;
  explicit Scene(vtkParticleSphereMapper* mapper)
  {
    this->Window->SetSize(420, 80);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 6; ++i)
    {
      points->InsertNextPoint(2.5 * i, 0.0, 0.0);
    }
    // a second row behind, so that density AO has something to find
    for (int i = 0; i < 6; ++i)
    {
      points->InsertNextPoint(2.5 * i, 0.0, -2.0);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    mapper->SetInputData(data);
    mapper->SetRadius(1.0);
    this->Actor->SetMapper(mapper);
    this->Actor->GetProperty()->SetColor(0.8, 0.8, 0.8);
    this->Actor->GetProperty()->SetAmbient(0.2);
    this->Actor->GetProperty()->SetDiffuse(0.8);
    this->Renderer->AddActor(this->Actor);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetParallelProjection(1);
    camera->SetFocalPoint(6.25, 0.0, 0.0);
    camera->SetPosition(6.25, 0.0, 50.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(1.35);
    this->Renderer->ResetCameraClippingRange();
    this->AO->SetDelegatePass(this->Steps);
    // the density at the visible point itself (fetch distance 0), so the front faces darken
    this->AO->GetDensityVolume()->SetDensityFactor(4.0);
    this->AO->SetFetchDistance(0.0);
  }
  // the red channel at the centre of each front particle
  std::vector<double> Centres(vtkRenderPass* pass)
  {
    this->Renderer->SetPass(pass);
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> rgba;
    this->Window->GetRGBACharPixelData(0, 0, 419, 79, 0, rgba);
    std::vector<double> values;
    for (int i = 0; i < 6; ++i)
    {
      const int x = static_cast<int>(std::lround((2.5 * i - 6.25) / (2.0 * 1.35) * 80.0 + 209.5));
      values.push_back(rgba->GetValue(4 * (40 * 420 + x)));
    }
    return values;
  }
};

bool CheckTint(const char* what, const std::vector<double>& plain,
  const std::vector<double>& tinted, double factor)
{
  bool ok = true;
  for (int i = 0; i < 6; ++i)
  {
    const double expected = (i % 2 == 1 ? factor : 1.0) * plain[i];
    std::cout << what << " particle " << i << ": " << tinted[i] << " (expected " << expected
              << ")\n";
    if (plain[i] < 40.0 || std::abs(tinted[i] - expected) > 2.0 + 0.02 * plain[i])
    {
      std::cerr << "FAIL: " << what << ": particle " << i << " is " << tinted[i] << ", expected "
                << expected << "\n";
      ok = false;
    }
  }
  return ok;
}

bool RunScene(const char* name, vtkParticleSphereMapper* mapper)
{
  Scene scene(mapper);
  bool ok = true;
  const std::vector<double> plain = scene.Centres(scene.Steps);
  scene.Tint->SetDelegatePass(scene.Steps);
  ok =
    CheckTint((std::string(name) + " tint").c_str(), plain, scene.Centres(scene.Tint), 0.5) && ok;
  // density AO alone, then under the tint: the occlusions multiply
  const std::vector<double> ao = scene.Centres(scene.AO);
  bool darker = false;
  for (int i = 0; i < 6; ++i)
  {
    darker = darker || ao[i] < plain[i] - 5.0;
  }
  if (!darker)
  {
    std::cerr << "FAIL: " << name << ": the density AO darkens nothing; composition untested\n";
    ok = false;
  }
  scene.Tint->SetDelegatePass(scene.AO);
  ok =
    CheckTint((std::string(name) + " tint+AO").c_str(), ao, scene.Centres(scene.Tint), 0.5) && ok;
  return ok;
}
}

int TestShaderHookContract(int, char*[])
{
  bool ok = true;
  vtkNew<vtkParticleSphereMapper> sphereMapper;
  ok = RunScene("sphere mapper", sphereMapper) && ok;
  vtkNew<vtkTransparentSphereMapper> transparentMapper;
  ok = RunScene("transparent mapper", transparentMapper) && ok;

  // a missing hook: one warning over several shader builds, the picture without the pass's code
  {
    vtkNew<vtkParticleSphereMapper> mapper;
    Scene scene(mapper);
    const std::vector<double> plain = scene.Centres(scene.Steps);
    vtkNew<prTest::MessageCounter> messages;
    messages->Observe(scene.Tint);
    scene.Tint->SetDelegatePass(scene.Steps);
    scene.Tint->Hook = "//PR::NoSuchHook::Impl";
    scene.Tint->Modified();
    std::vector<double> missing;
    for (int build = 0; build < 3; ++build)
    {
      scene.Tint->Factor = 0.4 + 0.1 * build; // new shader code: a rebuild each time
      scene.Tint->Modified();
      missing = scene.Centres(scene.Tint);
    }
    std::cout << "missing hook: " << scene.Tint->Builds << " builds, " << messages->Warnings
              << " warning(s): " << messages->LastWarning << "\n";
    if (scene.Tint->Builds < 3 || messages->Warnings != 1 ||
      messages->LastWarning.find("//PR::NoSuchHook::Impl") == std::string::npos)
    {
      std::cerr << "FAIL: a missing hook must warn exactly once, naming it\n";
      ok = false;
    }
    ok = CheckTint("missing hook", plain, missing, 1.0) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
