/**
 * A minimal glTF 2.0 binary (GLB) writer: flat-shaded triangle meshes with positions,
 * normals, indices and PBR metallic-roughness materials, nothing else. Enough to ship a
 * hand-modelled asset from a script, with no DOM (three's GLTFExporter needs FileReader).
 */
export type Vec3 = [number, number, number];

export interface PbrMaterial {
  name: string;
  /** sRGB colour as #rrggbb: glTF wants linear factors, converted on write. */
  color: string;
  metallic: number;
  roughness: number;
  doubleSided?: boolean;
}

interface Primitive {
  material: number;
  positions: number[];
  normals: number[];
}

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function srgbToLinear(c: number): number {
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

/** Collects faces per material; each face gets its own vertices so the shading is flat. */
export class FlatMeshBuilder {
  private readonly materials: PbrMaterial[] = [];
  private readonly primitives: Primitive[] = [];

  addMaterial(material: PbrMaterial): number {
    this.materials.push(material);
    this.primitives.push({ material: this.materials.length - 1, positions: [], normals: [] });
    return this.materials.length - 1;
  }

  /**
   * A triangle whose front faces away from `inside`, a point inside the solid it bounds:
   * winding is fixed here rather than by hand. Degenerate triangles are dropped.
   */
  triangle(material: number, a: Vec3, b: Vec3, c: Vec3, inside: Vec3): void {
    let n = cross(sub(b, a), sub(c, a));
    const length = Math.hypot(...n);
    if (length < 1e-9) return;
    const centroid: Vec3 = [(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3];
    let vertices = [a, b, c];
    if (dot(n, sub(centroid, inside)) < 0) {
      vertices = [a, c, b];
      n = [-n[0], -n[1], -n[2]];
    }
    const unit = n.map((v) => v / length);
    const primitive = this.primitives[material];
    for (const v of vertices) {
      primitive.positions.push(...v);
      primitive.normals.push(...unit);
    }
  }

  /** A planar convex polygon, fanned from its first vertex. */
  polygon(material: number, points: Vec3[], inside: Vec3): void {
    for (let i = 1; i + 1 < points.length; i++) this.triangle(material, points[0], points[i], points[i + 1], inside);
  }

  quad(material: number, a: Vec3, b: Vec3, c: Vec3, d: Vec3, inside: Vec3): void {
    this.polygon(material, [a, b, c, d], inside);
  }

  /** The GLB bytes: one node, one mesh, one primitive per material that has faces. */
  toGlb(name: string): Uint8Array {
    const chunks: Buffer[] = [];
    let byteLength = 0;
    const bufferViews: object[] = [];
    const accessors: object[] = [];
    const addView = (data: Buffer, target: number): number => {
      bufferViews.push({ buffer: 0, byteOffset: byteLength, byteLength: data.length, target });
      chunks.push(data);
      byteLength += data.length;
      const padding = (4 - (data.length % 4)) % 4;
      if (padding) {
        chunks.push(Buffer.alloc(padding));
        byteLength += padding;
      }
      return bufferViews.length - 1;
    };
    const primitives: object[] = [];
    for (const primitive of this.primitives) {
      const count = primitive.positions.length / 3;
      if (count === 0) continue;
      const positions = Float32Array.from(primitive.positions);
      const min = [Infinity, Infinity, Infinity];
      const max = [-Infinity, -Infinity, -Infinity];
      for (let i = 0; i < count; i++) {
        for (let c = 0; c < 3; c++) {
          min[c] = Math.min(min[c], positions[i * 3 + c]);
          max[c] = Math.max(max[c], positions[i * 3 + c]);
        }
      }
      const indices = count > 65535 ? Uint32Array.from({ length: count }, (_, i) => i) : Uint16Array.from({ length: count }, (_, i) => i);
      const positionView = addView(Buffer.from(positions.buffer), 34962);
      const normalView = addView(Buffer.from(Float32Array.from(primitive.normals).buffer), 34962);
      const indexView = addView(Buffer.from(indices.buffer), 34963);
      accessors.push({ bufferView: positionView, componentType: 5126, count, type: 'VEC3', min, max });
      accessors.push({ bufferView: normalView, componentType: 5126, count, type: 'VEC3' });
      accessors.push({ bufferView: indexView, componentType: indices instanceof Uint32Array ? 5125 : 5123, count, type: 'SCALAR' });
      const base = accessors.length - 3;
      primitives.push({ attributes: { POSITION: base, NORMAL: base + 1 }, indices: base + 2, material: primitive.material, mode: 4 });
    }
    const json = {
      asset: { version: '2.0', generator: 'Oceano scripts/glbWriter.ts' },
      scene: 0,
      scenes: [{ name, nodes: [0] }],
      nodes: [{ name, mesh: 0 }],
      meshes: [{ name, primitives }],
      materials: this.materials.map((m) => {
        const rgb = [1, 3, 5].map((i) => srgbToLinear(parseInt(m.color.slice(i, i + 2), 16) / 255));
        return {
          name: m.name,
          pbrMetallicRoughness: { baseColorFactor: [...rgb, 1], metallicFactor: m.metallic, roughnessFactor: m.roughness },
          ...(m.doubleSided ? { doubleSided: true } : {}),
        };
      }),
      accessors,
      bufferViews,
      buffers: [{ byteLength }],
    };
    let jsonBytes = Buffer.from(JSON.stringify(json), 'utf8');
    const jsonPadding = (4 - (jsonBytes.length % 4)) % 4;
    jsonBytes = Buffer.concat([jsonBytes, Buffer.alloc(jsonPadding, 0x20)]);
    const bin = Buffer.concat(chunks);
    const header = Buffer.alloc(12);
    const total = 12 + 8 + jsonBytes.length + 8 + bin.length;
    header.writeUInt32LE(0x46546c67, 0); // 'glTF'
    header.writeUInt32LE(2, 4);
    header.writeUInt32LE(total, 8);
    const chunkHeader = (length: number, type: number) => {
      const h = Buffer.alloc(8);
      h.writeUInt32LE(length, 0);
      h.writeUInt32LE(type, 4);
      return h;
    };
    return new Uint8Array(
      Buffer.concat([header, chunkHeader(jsonBytes.length, 0x4e4f534a), jsonBytes, chunkHeader(bin.length, 0x004e4942), bin]),
    );
  }
}
