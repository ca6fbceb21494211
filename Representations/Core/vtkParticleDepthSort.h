/**
 * @class   vtkParticleDepthSort
 * @brief   GPU radix sort of float keys (e.g. particle depths) with their indices, in compute
 * shaders
 *
 * Sorts count float32 keys ascending, stably, on the GPU and yields the permutation as a buffer
 * of uint32 indices that can be drawn directly (GL_ELEMENT_ARRAY_BUFFER, glDrawElements(GL_POINTS,
 * count, GL_UNSIGNED_INT, 0)). Typical use, once per frame, for back-to-front compositing:
 * @code
 *   sort->Reserve(window, n);                        // grows the buffers when needed
 *   vtkParticleComputeProgram::BindStorage(b, sort->GetKeyBuffer());
 *   ...dispatch your shader writing n float keys (e.g. -depth)...
 *   sort->Sort(n);                                   // issues the barriers it needs
 *   sort->GetIndexBuffer()->Bind();                  // the element array of your VAO
 *   glDrawElements(GL_POINTS, n, GL_UNSIGNED_INT, nullptr);
 * @endcode
 *
 * Order: keys are mapped to uint32 by the usual float flip (negative: all bits inverted; positive:
 * sign bit set), so -inf < negatives < -0 < +0 < positives < +inf; -0 and +0 are distinct keys
 * (-0 first). Every NaN, whatever its sign or payload, is mapped to 0xFFFFFFFF and sorts last, in
 * input order. Equal keys keep their input order (stable). After Sort() the key buffer holds the
 * sorted keys as floats (NaNs as the quiet NaN 0x7FFFFFFF) and the index buffer the permutation:
 * index[i] is the input position of the i-th smallest key.
 *
 * Algorithm: least-significant-digit radix sort (Harris, Sengupta and Owens, GPU Gems 3 ch. 39;
 * Merrill and Grimshaw's tile structure) with 4-bit digits, i.e. 8 passes of 16 buckets for 32
 * bits, on 1024-key tiles (256 invocations x 4 keys). Each pass runs
 * 1. RadixSortHistogram: per tile digit counts, written digit-major (counts[digit * tiles + tile]);
 * 2. RadixSortScan / RadixSortScanAdd: exclusive scan of those 16 * tiles counts, multi-level
 *    (every level reduces by 1024: one level up to 65536 keys, two up to 6.7e7, three up to
 *    6.9e10), so each (digit, tile) gets its first output position;
 * 3. RadixSortScatter: stable scatter. Each invocation counts its 4 keys per digit in registers
 *    and stores the counts in a shared [16 digits][256 invocations] array (two 16-bit counts per
 *    word); an exclusive scan along the invocations (two levels, no subgroup operations) gives
 *    each key its rank among the tile's keys of its digit; with CoalescedWrites the tile is first
 *    reordered in shared memory so that consecutive invocations write consecutive addresses.
 * Keys and indices ping-pong between the caller-visible pair (key buffer, index buffer) and a
 * scratch pair. The first pass reads the caller's floats and maps them on the fly and takes
 * index = position without reading; the last one writes float keys back.
 *
 * Skipped passes (SkipUniformDigits, on by default): one extra read of the keys computes the
 * bitwise AND and OR of all mapped keys; a digit where they agree is the same in every key and its
 * pass is skipped (e.g. the sign/exponent digits of depths of similar magnitude; all 8 when every
 * key is the same). Reading those two words back is one CPU-GPU synchronisation per Sort(). With
 * an odd number of remaining passes the mapped keys are first copied to the scratch side so the
 * result still ends in GetIndexBuffer()/GetKeyBuffer(); with none the indices are 0..count-1.
 * SkipUniformDigitsOff() always runs the 8 passes and never waits for the GPU.
 *
 * Cost: O(n) work and memory traffic: per pass one read of the keys (histogram) and one read and
 * write of keys and indices (scatter), plus 16 counts per 1024 keys. With count keys reserved the
 * GPU memory is 16 bytes per key (key and index buffers, scratch keys and indices) plus 0.4 %
 * for the counts (measured times: Documentation/Core.md). Multi-level rather than one work group
 * looping over all counts because at 1e8 keys there are 1.6e6 counts, which one work group would
 * scan serially. CoalescedWrites off: faster on llvmpipe (measured: Documentation/Core.md).
 *
 * Limits: every buffer must fit in one shader storage block, so count is at most about
 * GL_MAX_SHADER_STORAGE_BLOCK_SIZE / 4.0625 keys (the scratch key buffer also holds the counts):
 * 33 million keys with Mesa's 128 MiB, more than 1e8 with the 2 GiB of current NVIDIA and AMD
 * drivers. The number of tiles (count / 1024) must not exceed the dispatch limit
 * (GL_MAX_COMPUTE_WORK_GROUP_COUNT x times y, split as in vtkParticleComputeProgram). Reserve()
 * reports either limit. Requires OpenGL 4.3 (compute shaders); no subgroup operations; at most 19
 * KB of shared memory and 256 invocations per work group.
 *
 * GL state: Sort() binds its four buffers to the indexed GL_SHADER_STORAGE_BUFFER binding points
 * 0 (keys), 1 (indices), 2 (scratch keys), 3 (scratch indices) through vtkParticleComputeProgram's
 * storage layer and leaves them bound; it leaves no program bound and VTK's shader cache told so
 * (vtkParticleComputeProgram::Use()), so the caller's next draw binds its program through
 * vtkOpenGLShaderCache::ReadyShaderProgram as usual. It starts with a
 * glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT) (so the caller's shader writes of the keys are
 * seen) and ends with one for GL_ELEMENT_ARRAY, GL_VERTEX_ATTRIB_ARRAY, GL_SHADER_STORAGE and
 * GL_BUFFER_UPDATE, so the indices can be drawn, read by shaders or read back directly.
 * Every method expects the context given to Reserve() to be current.
 *
 * @sa vtkParticleComputeProgram
 */
#ifndef vtkParticleDepthSort_h
#define vtkParticleDepthSort_h

#include "vtkObject.h"

#include "vtkParticleRenderingCoreModule.h" // for export macro
#include <vector>                           // for std::vector

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkWindow;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleDepthSort : public vtkObject
{
public:
  static vtkParticleDepthSort* New();
  vtkTypeMacro(vtkParticleDepthSort, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Allocate the buffers for count keys in the (current) context and build the shaders. Grows
   * only: a smaller count than the capacity does nothing, a larger one re-allocates (the buffer
   * names stay the same, their contents are lost, so write the keys after Reserve()). Returns
   * false with an error that names the limit when the context is below OpenGL 4.3, when count
   * exceeds GL_MAX_SHADER_STORAGE_BLOCK_SIZE or the dispatch limits, or when allocation fails.
   */
  bool Reserve(vtkOpenGLRenderWindow* context, vtkIdType count);

  /** Keys the buffers can hold (0 before Reserve()). */
  vtkIdType GetCapacity() const { return this->Capacity; }

  /**
   * The key buffer: the caller writes count float32 keys (e.g. with its own compute shader, as
   * a shader storage buffer, vtkParticleComputeProgram::BindStorage) before Sort(); afterwards
   * it holds the sorted keys. Its handle is 0 before Reserve().
   */
  vtkOpenGLBufferObject* GetKeyBuffer();

  /**
   * Sort the first count keys of the key buffer ascending (stable). False (vtkErrorMacro) when
   * count exceeds the capacity or Reserve() was not called. count 0 does nothing.
   *
   * Progress: when the sort has observers of vtkCommand::ProgressEvent, it invokes the event
   * (call data: a double, the fraction of the radix passes issued) with 0 before the first pass
   * and after each pass, the last with 1. A software rasteriser such as llvmpipe runs each
   * dispatch when it is issued, so there the fraction is the work done; on a GPU the commands
   * run asynchronously and the sort is over in milliseconds, long before anyone sees it.
   */
  bool Sort(vtkIdType count);

  /**
   * The index buffer: after Sort(count), count uint32 indices into the keys' input order,
   * smallest key first. An element-array buffer object: Bind() makes it the element array of
   * the bound vertex array. Its handle never changes after Reserve().
   */
  vtkOpenGLBufferObject* GetIndexBuffer();

  ///@{
  /**
   * Skip the passes of digits that are the same in every key (default on). Costs one read of the
   * keys and one CPU-GPU synchronisation per Sort(); off runs all 8 passes asynchronously.
   */
  vtkSetMacro(SkipUniformDigits, bool);
  vtkGetMacro(SkipUniformDigits, bool);
  vtkBooleanMacro(SkipUniformDigits, bool);
  ///@}

  ///@{
  /**
   * Scatter through shared memory (default on): each tile's keys are first put in sorted order in
   * shared memory, so consecutive invocations write consecutive addresses (coalesced writes, as
   * in Harris et al. and Onesweep; what GPUs want). Off writes each key from the invocation that
   * read it: faster on llvmpipe, whose writes do not coalesce (measured: Documentation/Core.md).
   * Same result either way.
   */
  vtkSetMacro(CoalescedWrites, bool);
  vtkGetMacro(CoalescedWrites, bool);
  vtkBooleanMacro(CoalescedWrites, bool);
  ///@}

  /** Radix passes run by the last Sort() (0..8). */
  vtkGetMacro(LastNumberOfPasses, int);

  ///@{
  /**
   * GPU time of Sort() from a timer query (off by default). GetLastSortGPUSeconds() waits for the
   * GPU to finish the sort; 0 when no timed sort happened.
   */
  vtkSetMacro(CollectTimings, bool);
  vtkGetMacro(CollectTimings, bool);
  vtkBooleanMacro(CollectTimings, bool);
  double GetLastSortGPUSeconds();
  ///@}

  /** Delete the buffers, programs and timer query (the context must be current). */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleDepthSort();
  ~vtkParticleDepthSort() override;

  bool BuildPrograms();
  bool Scan(unsigned int offset, unsigned int length);
  // The 4-bit digits (their shifts) in which some keys differ: all 8 without SkipUniformDigits.
  std::vector<unsigned int> FindDifferingDigits(unsigned int count, bool& ok);
  // One stable counting pass per digit of `shifts` (histogram, scan, scatter), ping-ponging
  // between the two sides so that the last writes side A; the identity with no digit.
  bool RunPasses(const std::vector<unsigned int>& shifts, unsigned int count);

  vtkIdType Capacity = 0;
  bool SkipUniformDigits = true;
  bool CoalescedWrites = true;
  bool CollectTimings = false;
  int LastNumberOfPasses = 0;

private:
  vtkParticleDepthSort(const vtkParticleDepthSort&) = delete;
  void operator=(const vtkParticleDepthSort&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
