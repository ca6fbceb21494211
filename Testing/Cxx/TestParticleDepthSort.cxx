// vtkParticleDepthSort and vtkParticleComputeProgram: every sort is compared exactly with
// std::stable_sort of (mapped key, index) on the CPU, indices and keys, with the skipping of
// uniform digits on and off and with coalesced and direct writes. Needs OpenGL 4.3: an unsupported
// context is a failure, not a skip. No baseline image (the -V argument of the driver is ignored).
#include "prTestUtilities.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleDepthSort.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

bool Expect(bool condition, const std::string& what)
{
  if (!prTest::Check(condition, what))
  {
    ++Failures;
  }
  return condition;
}

std::uint32_t Bits(float f)
{
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof(u));
  return u;
}

float FromBits(std::uint32_t u)
{
  float f;
  std::memcpy(&f, &u, sizeof(f));
  return f;
}

// the documented order: float flip, every NaN last
std::uint32_t MapKey(float f)
{
  const std::uint32_t u = Bits(f);
  if ((u & 0x7FFFFFFFu) > 0x7F800000u)
  {
    return 0xFFFFFFFFu;
  }
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}

// radix passes the sort must run: one per 4-bit digit that is not the same in every key
int ExpectedPasses(const std::vector<float>& keys)
{
  std::uint32_t a = 0xFFFFFFFFu, o = 0u;
  for (float k : keys)
  {
    a &= MapKey(k);
    o |= MapKey(k);
  }
  int passes = 0;
  for (int shift = 0; shift < 32; shift += 4)
  {
    passes += ((a ^ o) >> shift) & 0xFu ? 1 : 0;
  }
  return keys.empty() ? 0 : passes;
}

template <typename T>
std::vector<T> ReadBuffer(vtkOpenGLBufferObject* buffer, std::size_t count)
{
  std::vector<T> data(count);
  if (count > 0)
  {
    vtkParticleComputeProgram::DownloadStorage(buffer, 0, count * sizeof(T), data.data());
  }
  return data;
}

// Compare the sort's result with std::stable_sort; print the first mismatches.
void CheckResult(
  vtkParticleDepthSort* sort, const std::string& name, const std::vector<float>& keys, bool skip)
{
  const std::size_t n = keys.size();
  std::vector<std::uint32_t> expected(n);
  std::iota(expected.begin(), expected.end(), 0u);
  std::stable_sort(expected.begin(), expected.end(),
    [&](std::uint32_t x, std::uint32_t y) { return MapKey(keys[x]) < MapKey(keys[y]); });

  const std::vector<std::uint32_t> indices = ReadBuffer<std::uint32_t>(sort->GetIndexBuffer(), n);
  const std::vector<float> sorted = ReadBuffer<float>(sort->GetKeyBuffer(), n);
  std::size_t badIndices = 0, badKeys = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (indices[i] != expected[i] && badIndices++ < 5)
    {
      std::cerr << "  " << name << ": index[" << i << "] = " << indices[i] << ", expected "
                << expected[i] << " (key " << keys[expected[i]] << ")\n";
    }
    const float want = keys[expected[i]];
    const bool same = std::isnan(want) ? std::isnan(sorted[i]) : Bits(sorted[i]) == Bits(want);
    if (!same && badKeys++ < 5)
    {
      std::cerr << "  " << name << ": key[" << i << "] = " << sorted[i] << ", expected " << want
                << "\n";
    }
  }
  const std::string mode = std::string(skip ? " (skipping" : " (8 passes") +
    (sort->GetCoalescedWrites() ? ")" : ", direct writes)");
  Expect(badIndices == 0,
    name + mode + ": " + std::to_string(badIndices) + " indices differ from std::stable_sort");
  Expect(badKeys == 0, name + mode + ": " + std::to_string(badKeys) + " sorted keys differ");
  const int passes = skip ? ExpectedPasses(keys) : (n ? 8 : 0);
  Expect(sort->GetLastNumberOfPasses() == passes,
    name + mode + ": " + std::to_string(sort->GetLastNumberOfPasses()) + " passes, expected " +
      std::to_string(passes));
}

// Upload the keys with glBufferSubData, sort, compare. Returns the GPU seconds.
double SortAndCheck(vtkOpenGLRenderWindow* context, vtkParticleDepthSort* sort,
  const std::string& name, const std::vector<float>& keys, bool skip)
{
  const vtkIdType n = static_cast<vtkIdType>(keys.size());
  sort->SetSkipUniformDigits(skip);
  if (!Expect(sort->Reserve(context, n), name + ": Reserve(" + std::to_string(n) + ")"))
  {
    return 0.0;
  }
  if (n > 0)
  {
    vtkParticleComputeProgram::UploadStorage(
      sort->GetKeyBuffer(), 0, n * sizeof(float), keys.data());
  }
  Expect(sort->Sort(n), name + ": Sort()");
  const double seconds = sort->GetLastSortGPUSeconds();
  CheckResult(sort, name, keys, skip);
  return seconds;
}

// GPU seconds of repeated sorts of the same keys (buffers warm): the minimum and the median.
void TimeSorts(vtkParticleDepthSort* sort, const std::string& name, const std::vector<float>& keys,
  bool skip, int repeats = 5)
{
  const vtkIdType n = static_cast<vtkIdType>(keys.size());
  sort->SetSkipUniformDigits(skip);
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r)
  {
    vtkParticleComputeProgram::UploadStorage(
      sort->GetKeyBuffer(), 0, n * sizeof(float), keys.data());
    const double start = vtkTimerLog::GetUniversalTime();
    sort->Sort(n);
    seconds.push_back(sort->GetLastSortGPUSeconds());
    const double wall = vtkTimerLog::GetUniversalTime() - start;
    if (r == 0)
    {
      std::cout << name << (skip ? "" : ", skipping off")
                << (sort->GetCoalescedWrites() ? "" : ", direct writes") << ": wall " << wall * 1e3
                << " ms, ";
    }
  }
  std::sort(seconds.begin(), seconds.end());
  std::cout << "GPU min " << seconds.front() * 1e3 << " ms, median "
            << seconds[seconds.size() / 2] * 1e3 << " ms over " << repeats << " sorts\n";
  Expect(seconds.front() > 0.0, name + ": the GPU timer gives a time");
}

std::vector<float> RandomKeys(std::size_t n, unsigned int seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(-1000.0f, 1000.0f);
  const float specials[] = { 0.0f, -0.0f, std::numeric_limits<float>::infinity(),
    -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
    FromBits(0xFFC00001u) /* negative NaN with a payload */,
    FromBits(0x7F800001u) /* signalling NaN */, std::numeric_limits<float>::denorm_min(),
    -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(),
    std::numeric_limits<float>::lowest(), 1.0f, -1.0f };
  std::vector<float> keys(n);
  for (float& key : keys)
  {
    const std::uint32_t r = random();
    if (r % 64 == 0)
    {
      key = specials[(r >> 8) % (sizeof(specials) / sizeof(specials[0]))];
    }
    else if (r % 64 == 1)
    {
      key = FromBits(static_cast<std::uint32_t>(random())); // any bit pattern, NaNs included
    }
    else
    {
      key = uniform(random);
      if (r % 64 < 16)
      {
        key = std::round(key / 50.0f); // many duplicates: stability matters
      }
    }
  }
  return keys;
}

// keys = base scaled by 1 + k ulps, k < 2^bits: only the low mantissa bits differ
std::vector<float> LowBitKeys(std::size_t n, int bits, float base, unsigned int seed)
{
  std::mt19937 random(seed);
  std::vector<float> keys(n);
  for (float& key : keys)
  {
    key = FromBits(Bits(base) + (static_cast<std::uint32_t>(random()) & ((1u << bits) - 1u)));
  }
  return keys;
}

// A compute shader writes the keys (the intended use); returns the keys it wrote.
std::vector<float> WriteKeysWithShader(
  vtkOpenGLRenderWindow* context, vtkParticleDepthSort* sort, unsigned int n)
{
  vtkNew<vtkParticleComputeProgram> program;
  program->SetSource("#version 430\n"
                     "layout(local_size_x = 64) in;\n"
                     "layout(std430, binding = 5) buffer Keys { float keys[]; };\n"
                     "uniform uint count;\n"
                     "uniform float scale;\n"
                     "void main() {\n"
                     "  uint i = gl_GlobalInvocationID.x;\n"
                     "  if (i < count) { keys[i] = scale * float((i * 7919u) % 1000u) - 500.0; }\n"
                     "}\n");
  std::vector<float> keys;
  if (!Expect(program->Build(context), "key shader builds"))
  {
    return keys;
  }
  program->Use();
  Expect(program->SetUniformui("count", n), "SetUniformui on an active uniform");
  Expect(program->SetUniformf("scale", 0.25f), "SetUniformf on an active uniform");
  Expect(!program->SetUniformf("absent", 1.0f), "SetUniformf on a missing uniform is false");
  vtkParticleComputeProgram::BindStorage(5, sort->GetKeyBuffer());
  Expect(program->Dispatch((n + 63) / 64), "key shader dispatch");
  glUseProgram(0);
  program->ReleaseGraphicsResources(context);
  keys.resize(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    keys[i] = 0.25f * static_cast<float>((i * 7919u) % 1000u) - 500.0f;
  }
  return keys;
}

// The index buffer drives a draw directly: glDrawElements(GL_POINTS) with it as the element
// buffer, captured by transform feedback, must see gl_VertexID == index[i] for every i.
void CheckDrawWithIndices(vtkParticleDepthSort* sort, std::size_t n)
{
  const char* source = "#version 430\n"
                       "out uint vertexId;\n"
                       "void main() { vertexId = uint(gl_VertexID); gl_Position = vec4(0.0); }\n";
  GLuint shader = glCreateShader(GL_VERTEX_SHADER);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  const char* varyings[] = { "vertexId" };
  glTransformFeedbackVaryings(program, 1, varyings, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program);
  glDeleteShader(shader);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (Expect(linked == GL_TRUE, "transform feedback program links"))
  {
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    sort->GetIndexBuffer()->Bind(); // the element array of the bound VAO
    vtkNew<vtkOpenGLBufferObject> captured;
    vtkParticleComputeProgram::AllocateStorage(captured, n * sizeof(std::uint32_t));
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLuint>(captured->GetHandle()));
    glUseProgram(program);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawElements(GL_POINTS, static_cast<GLsizei>(n), GL_UNSIGNED_INT, nullptr);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    glUseProgram(0);
    glBindVertexArray(0);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    const std::vector<std::uint32_t> drawn = ReadBuffer<std::uint32_t>(captured, n);
    const std::vector<std::uint32_t> indices = ReadBuffer<std::uint32_t>(sort->GetIndexBuffer(), n);
    Expect(drawn == indices, "glDrawElements with the index buffer fetches the sorted indices");
    captured->ReleaseGraphicsResources();
    glDeleteVertexArrays(1, &vao);
  }
  glDeleteProgram(program);
}

// Dispatch(x) above the x limit is split into a 2D grid; the linear group id (as
// prLinearGroupID() of Shaders/Core/ComputeCommon.glsl) numbers the groups.
void CheckDispatchSplit(vtkOpenGLRenderWindow* context)
{
  unsigned int limits[3];
  vtkParticleComputeProgram::GetMaxWorkGroupCount(context, limits);
  std::cout << "GL_MAX_COMPUTE_WORK_GROUP_COUNT: " << limits[0] << " " << limits[1] << " "
            << limits[2] << "\n";
  const unsigned int groups = limits[0] + 17;
  vtkNew<vtkParticleComputeProgram> program;
  program->SetSource("#version 430\n"
                     "layout(local_size_x = 1) in;\n"
                     "layout(std430, binding = 0) buffer Counter { uint hits; uint maxId; };\n"
                     "uniform uint groups;\n"
                     "void main() {\n"
                     "  uint g = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;\n"
                     "  if (g < groups) { atomicAdd(hits, 1u); atomicMax(maxId, g); }\n"
                     "}\n");
  if (!Expect(program->Build(context), "dispatch-split shader builds"))
  {
    return;
  }
  vtkNew<vtkOpenGLBufferObject> buffer;
  const GLuint zero[2] = { 0, 0 };
  vtkParticleComputeProgram::AllocateStorage(buffer, sizeof(zero));
  vtkParticleComputeProgram::UploadStorage(buffer, 0, sizeof(zero), zero);
  vtkParticleComputeProgram::BindStorage(0, buffer);
  program->Use();
  program->SetUniformui("groups", groups);
  Expect(program->Dispatch(groups), "Dispatch above the x limit");
  {
    vtkNew<prTest::MessageCounter> catcher; // errors only, while expected
    catcher->Observe(program, false, true);
    Expect(!program->Dispatch(limits[0] + 1, 2) &&
        catcher->LastError.find("GL_MAX_COMPUTE_WORK_GROUP_COUNT") != std::string::npos,
      "Dispatch above the x limit with y > 1 fails and names the limit");
    catcher->StopObserving();
  }
  glUseProgram(0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<std::uint32_t> result = ReadBuffer<std::uint32_t>(buffer, 2);
  Expect(result[0] == groups && result[1] == groups - 1,
    "split dispatch ran " + std::to_string(result[0]) + " groups up to id " +
      std::to_string(result[1]) + ", expected " + std::to_string(groups));
  buffer->ReleaseGraphicsResources();
  program->ReleaseGraphicsResources(context);
}
}

int TestParticleDepthSort(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(16, 16);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!Expect(context != nullptr, "an OpenGL render window"))
  {
    return EXIT_FAILURE;
  }
  context->MakeCurrent();
  std::cout << "OpenGL: " << glGetString(GL_VERSION) << " (" << glGetString(GL_RENDERER) << ")\n";
  std::string reason;
  if (!Expect(vtkParticleComputeProgram::IsSupported(context, &reason),
        "compute shaders supported: " + reason))
  {
    return EXIT_FAILURE;
  }

  CheckDispatchSplit(context);

  vtkNew<vtkParticleDepthSort> sort;
  sort->SetCollectTimings(true);
  // (skipping, coalesced writes): the default, all 8 passes, direct writes
  for (int configuration = 0; configuration < 3; ++configuration)
  {
    const bool skip = configuration != 1;
    sort->SetCoalescedWrites(configuration != 2);
    for (std::size_t n : { 0, 1, 2, 1023, 1024, 1025 })
    {
      SortAndCheck(context, sort, "random " + std::to_string(n), RandomKeys(n, 11 + n), skip);
    }
    const std::vector<float> hundredThousand = RandomKeys(100000, 5);
    SortAndCheck(context, sort, "random 1e5", hundredThousand, skip);
    if (configuration == 0)
    {
      CheckDrawWithIndices(sort, hundredThousand.size());
    }
    TimeSorts(sort, "1e5 random keys", hundredThousand, skip);
    SortAndCheck(context, sort, "all equal", std::vector<float>(5000, 3.5f), skip);
    SortAndCheck(context, sort, "all NaN",
      { std::nanf(""), FromBits(0xFFC00000u), FromBits(0x7F800001u), std::nanf("") }, skip);
    std::vector<float> ascending = RandomKeys(5000, 7);
    std::sort(
      ascending.begin(), ascending.end(), [](float a, float b) { return MapKey(a) < MapKey(b); });
    SortAndCheck(context, sort, "already sorted", ascending, skip);
    std::vector<float> descending(ascending.rbegin(), ascending.rend());
    SortAndCheck(context, sort, "reverse sorted", descending, skip);
    // equal high bytes: 2 passes (even), 3 passes (odd: the keys are copied first), 1 pass
    SortAndCheck(context, sort, "low 8 bits differ", LowBitKeys(70000, 8, 12.0f, 3), skip);
    SortAndCheck(context, sort, "low 12 bits differ", LowBitKeys(70000, 12, -7.0f, 4), skip);
    SortAndCheck(context, sort, "low 3 bits differ", LowBitKeys(3000, 3, 0.5f, 5), skip);
    std::vector<float> twoWays = LowBitKeys(50000, 8, 2.0f, 6); // digits 0, 1 and the sign
    for (std::size_t i = 0; i < twoWays.size(); i += 3)
    {
      twoWays[i] = -twoWays[i];
    }
    SortAndCheck(context, sort, "low bits and sign differ", twoWays, skip);

    const std::vector<float> million = RandomKeys(1000000, 1);
    SortAndCheck(context, sort, "random 1e6", million, skip);
    TimeSorts(sort, "1e6 random keys", million, skip);
    if (configuration == 0)
    {
      const double start = vtkTimerLog::GetUniversalTime();
      std::vector<std::uint32_t> order(million.size());
      std::iota(order.begin(), order.end(), 0u);
      std::stable_sort(order.begin(), order.end(),
        [&](std::uint32_t x, std::uint32_t y) { return MapKey(million[x]) < MapKey(million[y]); });
      std::cout << "1e6 random keys, CPU std::stable_sort for comparison: "
                << (vtkTimerLog::GetUniversalTime() - start) * 1e3 << " ms\n";
      TimeSorts(
        sort, "1e6 keys, low 8 bits differ (2 passes)", LowBitKeys(1000000, 8, 3.0f, 9), skip);
    }
    const int keyBuffer = sort->GetKeyBuffer()->GetHandle();
    const int indexBuffer = sort->GetIndexBuffer()->GetHandle();
    // smaller after larger: the buffers are reused
    SortAndCheck(context, sort, "random 3000 after 1e6", RandomKeys(3000, 2), skip);
    Expect(sort->GetCapacity() >= 1000000, "capacity kept after a smaller sort");
    // larger after smaller: growth keeps the buffer names
    SortAndCheck(context, sort, "random 1.2e6+ (growth)",
      RandomKeys(1200000 + 100000 * configuration, 3), skip);
    Expect(sort->GetKeyBuffer()->GetHandle() == keyBuffer &&
        sort->GetIndexBuffer()->GetHandle() == indexBuffer,
      "buffer names kept through growth");
  }

  // keys written by a compute shader (the caller's barrier is Sort()'s business)
  sort->SetSkipUniformDigits(true);
  Expect(sort->Reserve(context, 300000), "Reserve for shader-written keys");
  std::vector<float> shaderKeys = WriteKeysWithShader(context, sort, 300000);
  Expect(sort->Sort(300000), "Sort of shader-written keys");
  CheckResult(sort, "shader-written keys", shaderKeys, true);

  // a fresh object growing from small to large
  vtkNew<vtkParticleDepthSort> growing;
  SortAndCheck(context, growing, "fresh 10", RandomKeys(10, 21), true);
  SortAndCheck(context, growing, "fresh 200000 after 10", RandomKeys(200000, 22), true);
  growing->ReleaseGraphicsResources(context);

  // errors: beyond the capacity, beyond the GPU limits (the message names the limit)
  {
    vtkNew<prTest::MessageCounter> catcher; // errors only, while expected
    catcher->Observe(sort, false, true);
    std::string& lastError = catcher->LastError;
    const vtkIdType capacity = sort->GetCapacity();
    Expect(!sort->Sort(capacity + 1), "Sort beyond the capacity fails");
    Expect(!lastError.empty(), "Sort beyond the capacity reports an error");
    lastError.clear();
    GLint64 blockLimit = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockLimit);
    Expect(!sort->Reserve(context, static_cast<vtkIdType>(blockLimit / 4)),
      "Reserve beyond GL_MAX_SHADER_STORAGE_BLOCK_SIZE fails");
    std::cout << "over-limit message: " << lastError;
    Expect(lastError.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE") != std::string::npos &&
        lastError.find(std::to_string(blockLimit)) != std::string::npos,
      "the over-limit message names the limit and its value");
    Expect(sort->GetCapacity() == capacity, "a failed Reserve keeps the buffers");
    catcher->StopObserving();
  }

  sort->ReleaseGraphicsResources(context);
  Expect(
    sort->GetKeyBuffer()->GetHandle() == 0 && sort->GetCapacity() == 0, "ReleaseGraphicsResources");
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
