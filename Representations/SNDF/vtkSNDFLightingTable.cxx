#include "vtkSNDFLightingTable.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <algorithm>

namespace
{
// The lighting table's fragment shader (Eqs. 12-14): per bin and row, the least-squares plane of
// the lit value over the part of the bin inside the disk.
std::string LightingTableMain()
{
  return "ivec2 prTexel = ivec2(texCoord * vec2(float(prBins * prBins), float(prTableRows)));\n"
         "  int prRow = prTexel.y;\n"
         "  int prLight = (prRow == 1 || prRow == 4 || prRow == 5) ? 1 : 0;\n"
         "  float prN = 0.0;\n"
         "  vec2 prU = vec2(0.0);\n"
         "  vec3 prUU = vec3(0.0);\n"
         "  vec3 prF = vec3(0.0);\n"
         "  vec3 prUFx = vec3(0.0);\n"
         "  vec3 prUFy = vec3(0.0);\n"
         "  for (int i = 0; i < prSubsamples; ++i)\n"
         "  {\n"
         "    for (int j = 0; j < prSubsamples; ++j)\n"
         "    {\n"
         "      vec2 prUV = (vec2(i, j) + 0.5) / float(prSubsamples);\n"
         "      vec3 prNormal;\n"
         "      if (prSNDFBinPoint(prTexel.x, prBins, prUV, prNormal))\n"
         "      {\n"
         "        vec3 prValue = prRow == 6 ? vec3(0.0) : prLightSum(prNormal, prLight);\n"
         "        prN += 1.0;\n"
         "        prU += prUV;\n"
         "        prUU += vec3(prUV.x * prUV.x, prUV.x * prUV.y, prUV.y * prUV.y);\n"
         "        prF += prValue;\n"
         "        prUFx += prUV.x * prValue;\n"
         "        prUFy += prUV.y * prValue;\n"
         "      }\n"
         "    }\n"
         "  }\n"
         "  vec3 prOut = vec3(0.0);\n"
         "  if (prN == 0.0)\n"
         "  {\n"
         "    // a bin outside the disk holds no sample; give it the normal of the rim point "
         "nearest\n"
         "    // to its centre and no slope\n"
         "    vec3 prCentre;\n"
         "    prSNDFBinPoint(prTexel.x, prBins, vec2(0.5), prCentre);\n"
         "    vec2 prRim = normalize(prCentre.xy) * 0.9999;\n"
         "    vec3 prValue = prLightSum(vec3(prRim, sqrt(max(0.0, 1.0 - dot(prRim, prRim)))), "
         "prLight);\n"
         "    prOut = prRow < 2 ? prValue : (prRow == 6 ? vec3(0.5, 0.5, 0.0) : vec3(0.0));\n"
         "  }\n"
         "  else\n"
         "  {\n"
         "    // least-squares plane f = mean + slope . (u - centroid) over bin ∩ disk (the\n"
         "    // covariance regularised by 1e-4: a sliver of a bin at the rim gets no slope across "
         "it)\n"
         "    vec2 prMeanU = prU / prN;\n"
         "    vec3 prMeanF = prF / prN;\n"
         "    float prCxx = prUU.x / prN - prMeanU.x * prMeanU.x + 1.0e-4;\n"
         "    float prCxy = prUU.y / prN - prMeanU.x * prMeanU.y;\n"
         "    float prCyy = prUU.z / prN - prMeanU.y * prMeanU.y + 1.0e-4;\n"
         "    vec3 prCxf = prUFx / prN - prMeanU.x * prMeanF;\n"
         "    vec3 prCyf = prUFy / prN - prMeanU.y * prMeanF;\n"
         "    float prDet = prCxx * prCyy - prCxy * prCxy;\n"
         "    vec3 prSlopeX = (prCyy * prCxf - prCxy * prCyf) / prDet;\n"
         "    vec3 prSlopeY = (prCxx * prCyf - prCxy * prCxf) / prDet;\n"
         "    prOut = prRow < 2 ? prMeanF\n"
         "      : (prRow == 6 ? vec3(prMeanU, 0.0)\n"
         "      : ((prRow == 2 || prRow == 4) ? prSlopeX : prSlopeY));\n"
         "  }\n"
         "  gl_FragData[0] = vec4(prOut, 1.0);\n";
}
}

//------------------------------------------------------------------------------
vtkSNDFLightingTable::vtkSNDFLightingTable() = default;

//------------------------------------------------------------------------------
vtkSNDFLightingTable::~vtkSNDFLightingTable() = default;

//------------------------------------------------------------------------------
bool vtkSNDFLightingTable::Build(vtkOpenGLRenderer* ren, vtkOpenGLRenderWindow* context,
  vtkCamera* camera, vtkProperty* material, int bins, const std::vector<double>& key)
{
  vtkOpenGLState* ostate = context->GetState();
  const std::string uniforms = ren->GetLightingUniforms();
  const int complexity = ren->GetLightingComplexity();
  const int count = ren->GetLightingCount();
  std::string body = "vec3 prLightSum(vec3 normalVCVSOutput, int row)\n{\n"
                     "  float specularPower = prSpecularPower;\n"
                     "  vec4 vertexVC = vec4(0.0, 0.0, -prViewDistance, 1.0);\n" +
    vtkParticleSphereMapper::GetLightSumCode(complexity, count) +
    "  return row == 0 ? diffuse : specular;\n}\n";
  const std::string source = uniforms + "\n" + body;
  if (!this->Quad || source != this->QuadSource)
  {
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(
      fs, "//VTK::FSQ::Decl", vtkParticleShaders::Get("SNDFLightingTable") + "\n" + source);
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", LightingTableMain());
    this->Quad.reset(new vtkOpenGLQuadHelper(context, nullptr, fs.c_str(), nullptr));
    this->QuadSource = source;
  }
  vtkOpenGLQuadHelper* quad = this->Quad.get();
  if (!quad->Program)
  {
    return false;
  }
  if (this->Bins != bins || !this->Table->GetHandle())
  {
    this->Table->SetContext(context);
    this->Table->SetInternalFormat(GL_RGBA32F);
    this->Table->SetFormat(GL_RGBA);
    this->Table->SetDataType(GL_FLOAT);
    this->Table->Allocate2D(bins * bins, Rows, 4, VTK_FLOAT);
    this->Target->SetContext(context);
    ostate->PushFramebufferBindings();
    this->Target->Bind();
    this->Target->AddColorAttachment(0, this->Table);
    this->Target->ActivateDrawBuffers(1);
    ostate->PopFramebufferBindings();
    this->Bins = bins;
  }
  context->GetShaderCache()->ReadyShaderProgram(quad->Program);
  ren->UpdateLightingUniforms(quad->Program);
  quad->Program->SetUniformi("prBins", bins);
  quad->Program->SetUniformi("prTableRows", Rows);
  quad->Program->SetUniformi("prSubsamples", std::max(32, SubsamplesPerAxis / bins));
  quad->Program->SetUniformf("prSpecularPower", static_cast<float>(material->GetSpecularPower()));
  quad->Program->SetUniformf("prViewDistance", static_cast<float>(camera->GetDistance()));
  ostate->PushFramebufferBindings();
  this->Target->Bind();
  this->Target->ActivateDrawBuffers(1);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglViewport(0, 0, bins * bins, Rows);
    ostate->vtkglScissor(0, 0, bins * bins, Rows);
    quad->Render();
  }
  ostate->PopFramebufferBindings();
  this->Key = key;
  this->Have = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFLightingTable::Read(vtkFloatArray* table)
{
  if (!table || !this->Have || !this->Table->GetHandle())
  {
    return false;
  }
  const int n = this->Bins * this->Bins;
  std::vector<float> texels(static_cast<std::size_t>(n) * Rows * 4);
  this->Table->Bind();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, texels.data());
  table->SetNumberOfComponents(3);
  table->SetNumberOfTuples(Rows * n);
  for (int t = 0; t < Rows * n; ++t)
  {
    table->SetTypedTuple(t, &texels[4 * static_cast<std::size_t>(t)]);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkSNDFLightingTable::GetTexture() const
{
  return this->Table;
}

//------------------------------------------------------------------------------
void vtkSNDFLightingTable::Release(vtkWindow* w)
{
  this->Table->ReleaseGraphicsResources(w);
  this->Target->ReleaseGraphicsResources(w);
  this->Have = false;
  this->Bins = 0;
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(w);
    this->Quad.reset();
  }
  this->Key.clear();
}
