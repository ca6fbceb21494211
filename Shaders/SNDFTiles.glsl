//=========================================================================
// SNDFTiles.glsl -- where an S-NDF lives in the S-MIP cache of
// vtkSNDFRenderPass (Ibrahim et al. 2017, Sec. 6.1, Fig. 9).
//
// The S-NDFs of a level of the S-MIP are texels of a virtual image plane, cut
// into prTileSize^2 tiles; the cache is a pool of tile slots, and texel
// (x, y) of the tile in slot s is number s * prTileTexels + y * prTileSize + x
// of the pool (bins: prWordsPerPixel words each, sums: 4 vec4 each). The page
// table of one dispatch maps a rectangle of tiles (prTilesX wide, row by row)
// to their slots, -1 where a tile is not in the cache; prTexelOffset is the
// texel of the rectangle that position (0, 0) of the dispatch reads (for the
// window's pixels: the window's lower-left texel, in [0, prTileSize)^2).
//=========================================================================

const int prTileSize = 64;
const uint prTileTexels = 4096u;

layout(std430, binding = 2) readonly buffer prPageBuffer
{
  int prPageTable[];
};
uniform ivec2 prTexelOffset;
uniform int prTilesX;

// The pool texel of position p (p + prTexelOffset >= 0); false where its tile is not mapped.
bool prSNDFFindTexel(ivec2 p, out uint texel)
{
  ivec2 t = p + prTexelOffset;
  ivec2 tile = t / prTileSize;
  ivec2 local = t - tile * prTileSize;
  int slot = prPageTable[tile.y * prTilesX + tile.x];
  texel = uint(max(slot, 0)) * prTileTexels + uint(local.y * prTileSize + local.x);
  return slot >= 0;
}
