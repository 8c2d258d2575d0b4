/**
 * Leaves drawn by vertex pulling: one plain (non-instanced) draw of `leaves × indices` vertices,
 * whose vertex shader finds its leaf and corner from `gl_VertexID` and reads the leaf's matrix
 * and tint from float textures and the corner from a small texture of the leaf mesh. The pixels
 * are those of an `InstancedMesh` of the same arrays (three's instancing chunks run unchanged on
 * a local `instanceMatrix`), but software WebGL (SwiftShader, the headless browsers and GPU-less
 * machines) runs every instance of an instanced draw as a draw of its own: the default tree's
 * 37,500 leaves took 480 ms to draw instanced and 150 ms pulled, and the whole frame with its
 * shadows fell from about 1.15 s to 0.6 s. On a GPU both are a few milliseconds.
 *
 * Texture layouts (float, nearest, no mipmaps):
 * - matrices: `4 · LEAVES_PER_ROW` × rows RGBA; leaf `i`'s column-major matrix is the four texels
 *   from `(4 · (i mod LEAVES_PER_ROW), ⌊i / LEAVES_PER_ROW⌋)` on (the transferred array's 16
 *   floats per leaf, copied as they are);
 * - tints: `LEAVES_PER_ROW` × rows RGB, leaf `i` at `(i mod LEAVES_PER_ROW, ⌊i / LEAVES_PER_ROW⌋)`;
 * - leaf mesh: `max(V, I)` × 3 RGBA: row 0 the corners' positions with u in w, row 1 their
 *   normals with v in w, row 2 the triangle list's vertex indices in x.
 * The main thread only copies the transferred arrays into the textures' storage (a bulk copy,
 * no per-leaf loop); rows are allocated [`ROW_STEP`] at a time, so a texture is replaced only
 * when the leaves outgrow it or shrink to under half of it.
 */
import {
  BufferGeometry,
  DataTexture,
  FloatType,
  NearestFilter,
  RGBAFormat,
  RGBFormat,
  type IUniform,
  type Material,
  type PixelFormat,
} from 'three';
import type { LeafMeshBuffers } from '../core/types';

/** Leaves per texture row (the matrix texture is 4096 texels wide). */
export const LEAVES_PER_ROW = 1024;

/** Texture rows are allocated in steps of this many (8,192 leaves). */
export const ROW_STEP = 8;

/** Marks a vertex shader as pulled (and keys its program). */
export const LEAF_PULL_MARKER = '// sylva-leaf-pull';

/** The uniforms a pulled-leaf shader reads (shared by the leaf and shadow materials). */
export interface LeafPullUniforms {
  sylvaLeafMatrices: IUniform<DataTexture | null>;
  sylvaLeafTints: IUniform<DataTexture | null>;
  sylvaLeafMesh: IUniform<DataTexture | null>;
  /** Indices per leaf (the leaf mesh's triangle list length). */
  sylvaLeafIndices: IUniform<number>;
}

/** Declarations, before the body's first chunk: the instancing chunks then use the locals. */
const PULL_PARS = `${LEAF_PULL_MARKER}
#define USE_INSTANCING
#define SYLVA_LEAVES_PER_ROW ${LEAVES_PER_ROW}
uniform highp sampler2D sylvaLeafMatrices;
uniform highp sampler2D sylvaLeafTints;
uniform highp sampler2D sylvaLeafMesh;
uniform int sylvaLeafIndices;
`;

/** Start of `main()`: this vertex's leaf and corner, hiding the (absent) attributes. */
const PULL_MAIN = `
  int sylvaLeaf = gl_VertexID / sylvaLeafIndices;
  int sylvaCorner = int(texelFetch(sylvaLeafMesh, ivec2(gl_VertexID - sylvaLeaf * sylvaLeafIndices, 2), 0).x);
  vec4 sylvaCornerA = texelFetch(sylvaLeafMesh, ivec2(sylvaCorner, 0), 0);
  vec4 sylvaCornerB = texelFetch(sylvaLeafMesh, ivec2(sylvaCorner, 1), 0);
  vec3 position = sylvaCornerA.xyz;
  vec3 normal = sylvaCornerB.xyz;
  vec2 uv = vec2(sylvaCornerA.w, sylvaCornerB.w);
  ivec2 sylvaAt = ivec2(sylvaLeaf % SYLVA_LEAVES_PER_ROW, sylvaLeaf / SYLVA_LEAVES_PER_ROW);
  ivec2 sylvaColumn = ivec2(sylvaAt.x * 4, sylvaAt.y);
  mat4 instanceMatrix = mat4(
    texelFetch(sylvaLeafMatrices, sylvaColumn, 0),
    texelFetch(sylvaLeafMatrices, sylvaColumn + ivec2(1, 0), 0),
    texelFetch(sylvaLeafMatrices, sylvaColumn + ivec2(2, 0), 0),
    texelFetch(sylvaLeafMatrices, sylvaColumn + ivec2(3, 0), 0));
  vec3 color = texelFetch(sylvaLeafTints, sylvaAt, 0).rgb;
`;

/** The new uniforms (no textures yet). */
export function createLeafPullUniforms(): LeafPullUniforms {
  return {
    sylvaLeafMatrices: { value: null },
    sylvaLeafTints: { value: null },
    sylvaLeafMesh: { value: null },
    sylvaLeafIndices: { value: 1 },
  };
}

/** Rewrites a standard vertex shader to pull its leaf (exported for tests). */
export function pullLeafVertexShader(vertexShader: string): string {
  if (vertexShader.includes(LEAF_PULL_MARKER)) return vertexShader;
  const main = 'void main() {';
  if (!vertexShader.includes(main)) throw new Error('leaf pull: the vertex shader has no main()');
  return `${PULL_PARS}${vertexShader.replace(main, `${main}${PULL_MAIN}`)}`;
}

/**
 * Makes `material` draw pulled leaves (after any earlier `onBeforeCompile`, e.g. the wind's,
 * whose leaf code reads `instanceMatrix`). Its colours are the leaves' tints (`vertexColors`).
 */
export function applyLeafPull(material: Material, uniforms: LeafPullUniforms): void {
  const previous = material.onBeforeCompile.bind(material);
  const previousKey = material.customProgramCacheKey.bind(material);
  material.onBeforeCompile = (shader, renderer) => {
    previous(shader, renderer);
    shader.vertexShader = pullLeafVertexShader(shader.vertexShader);
    Object.assign(shader.uniforms, uniforms);
  };
  material.customProgramCacheKey = () => `${previousKey()}-sylva-leaf-pull`;
  material.needsUpdate = true;
}

/** A float texture of `width × height` texels over `data` (sized to fit). */
function floatTexture(
  data: Float32Array,
  width: number,
  height: number,
  format: PixelFormat,
): DataTexture {
  const texture = new DataTexture(data, width, height, format, FloatType);
  // three leaves RGB + FLOAT unsized, which WebGL 2 cannot allocate.
  texture.internalFormat = format === RGBAFormat ? 'RGBA32F' : 'RGB32F';
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  return texture;
}

/** One per-leaf texture (`texels` texels and `channels` floats per leaf) and its storage. */
class LeafTable {
  private texture: DataTexture | null = null;

  constructor(
    private readonly texels: number,
    private readonly channels: 3 | 4,
  ) {}

  /**
   * Copies `source` (`count` leaves) in; returns the texture, new only when the leaves outgrow
   * its rows or fill less than half of them (rows come in steps of [`ROW_STEP`], so a drag of
   * the leaf count copies into the same texture instead of allocating one a step).
   */
  set(source: Float32Array, count: number): DataTexture | null {
    if (count === 0) return this.texture;
    const rows = Math.ceil(count / LEAVES_PER_ROW);
    let texture = this.texture;
    const have = texture?.image.height ?? 0;
    if (!texture || have < rows || (have > ROW_STEP && rows <= have / 2)) {
      texture?.dispose();
      const width = LEAVES_PER_ROW * this.texels;
      const capacity = Math.ceil(rows / ROW_STEP) * ROW_STEP;
      const data = new Float32Array(width * capacity * this.channels);
      texture = floatTexture(data, width, capacity, this.channels === 4 ? RGBAFormat : RGBFormat);
      this.texture = texture;
    }
    const data = texture.image.data as Float32Array;
    const length = count * this.texels * this.channels;
    data.set(length === source.length ? source : source.subarray(0, length));
    texture.needsUpdate = true;
    return texture;
  }

  dispose(): void {
    this.texture?.dispose();
    this.texture = null;
  }
}

/**
 * The pulled leaves' data on the GPU: matrix, tint and leaf-mesh textures, the uniforms that
 * point at them, and the draw range of the geometry that draws them (which has no attributes).
 */
export class LeafPullData {
  readonly uniforms = createLeafPullUniforms();
  /** The geometry drawn: no attributes, `leaves × indices` vertices. */
  readonly geometry = new BufferGeometry();
  private readonly matrices = new LeafTable(4, 4);
  private readonly tints = new LeafTable(1, 3);
  private meshTexture: DataTexture | null = null;
  private leaves = 0;
  private indices = 0;

  /** Number of leaves. */
  get count(): number {
    return this.leaves;
  }

  /** Vertices drawn (0: nothing to draw). */
  get vertexCount(): number {
    return this.leaves * this.indices;
  }

  /** New per-leaf matrices (16 floats each, column-major) and tints (3 floats each). */
  setInstances(matrices: Float32Array, tints: Float32Array): void {
    const count = tints.length / 3;
    if (matrices.length < count * 16) {
      throw new Error(`leaf pull: ${matrices.length / 16} matrices for ${count} leaves`);
    }
    this.leaves = count;
    this.uniforms.sylvaLeafMatrices.value = this.matrices.set(matrices, count);
    this.uniforms.sylvaLeafTints.value = this.tints.set(tints, count);
    this.updateRange();
  }

  /** A new leaf mesh (every leaf draws it). */
  setMesh(leaf: LeafMeshBuffers): void {
    const vertices = leaf.positions.length / 3;
    const indices = leaf.indices.length;
    const width = Math.max(vertices, indices, 1);
    let texture = this.meshTexture;
    if (!texture || texture.image.width !== width) {
      texture?.dispose();
      texture = floatTexture(new Float32Array(width * 3 * 4), width, 3, RGBAFormat);
      this.meshTexture = texture;
    }
    const data = texture.image.data as Float32Array;
    data.fill(0);
    for (let k = 0; k < vertices; k++) {
      const a = k * 4;
      const b = (width + k) * 4;
      data[a] = leaf.positions[k * 3]!;
      data[a + 1] = leaf.positions[k * 3 + 1]!;
      data[a + 2] = leaf.positions[k * 3 + 2]!;
      data[a + 3] = leaf.uvs[k * 2]!;
      data[b] = leaf.normals[k * 3]!;
      data[b + 1] = leaf.normals[k * 3 + 1]!;
      data[b + 2] = leaf.normals[k * 3 + 2]!;
      data[b + 3] = leaf.uvs[k * 2 + 1]!;
    }
    for (let k = 0; k < indices; k++) data[(2 * width + k) * 4] = leaf.indices[k]!;
    texture.needsUpdate = true;
    this.indices = indices;
    this.uniforms.sylvaLeafMesh.value = texture;
    this.uniforms.sylvaLeafIndices.value = Math.max(indices, 1);
    this.updateRange();
  }

  private updateRange(): void {
    this.geometry.setDrawRange(0, this.vertexCount);
  }

  /**
   * Releases the textures (their GPU storage and their copies of the arrays) while no pulled
   * leaves are shown; the next `setMesh` and `setInstances` make new ones.
   */
  release(): void {
    this.matrices.dispose();
    this.tints.dispose();
    this.meshTexture?.dispose();
    this.meshTexture = null;
    this.uniforms.sylvaLeafMatrices.value = null;
    this.uniforms.sylvaLeafTints.value = null;
    this.uniforms.sylvaLeafMesh.value = null;
    this.leaves = 0;
    this.indices = 0;
    this.updateRange();
  }

  /** Releases the textures and the geometry. */
  dispose(): void {
    this.release();
    this.geometry.dispose();
  }
}
