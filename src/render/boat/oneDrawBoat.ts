import {
  BufferAttribute,
  BufferGeometry,
  DataTexture,
  DoubleSide,
  FloatType,
  FrontSide,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  NearestFilter,
  RGBAFormat,
  type Object3D,
} from 'three';
import { mergeGeometries } from 'three/addons/utils/BufferGeometryUtils.js';

/** What may differ between the model's materials: what each vertex or the small table below carries. */
const PER_PART = new Set(['uuid', 'id', 'name', 'color', 'roughness', 'metalness', 'side', 'userData', 'version']);

/** Whether the materials are alike but for colour, roughness, metalness and sides (plain PBR, no maps). */
function mergeable(materials: MeshStandardMaterial[]): boolean {
  const [first] = materials;
  const json = (m: MeshStandardMaterial) =>
    JSON.stringify(Object.entries(m.toJSON() as unknown as Record<string, unknown>).filter(([key]) => !PER_PART.has(key)));
  return materials.every(
    (m) => m.type === 'MeshStandardMaterial' && (m.side === FrontSide || m.side === DoubleSide) && json(m) === json(first),
  );
}

/** A triangle list's copy facing the other way: each triangle's order reversed, its normals negated. */
function turnedOver(geometry: BufferGeometry): BufferGeometry {
  const copy = geometry.clone();
  for (const name of Object.keys(copy.attributes)) {
    const attribute = copy.getAttribute(name) as BufferAttribute;
    const size = attribute.itemSize;
    const source = attribute.array.slice();
    for (let v = 0; v < attribute.count; v++) {
      const from = v - (v % 3) + 2 - (v % 3); // 0 1 2 → 2 1 0
      for (let c = 0; c < size; c++) attribute.array[v * size + c] = (name === 'normal' ? -1 : 1) * source[from * size + c];
    }
  }
  return copy;
}

/**
 * The loaded boat in one draw: its parts' triangles in one mesh with one standard material,
 * each vertex carrying its part's colour (linear, as the material held it) and a texture
 * coordinate into a one-row float table of (·, roughness, metalness), read as the roughness
 * and metalness maps (green and blue, as glTF's). A double-sided part is drawn as its
 * triangles twice, the copy turned over, as three.js would shade its back. The shading is the
 * parts' own; only the number of draws changes. A model whose parts differ in anything else
 * (maps, transparency, emission) is returned as it is.
 */
export function oneDrawBoat(model: Object3D): Object3D {
  const meshes: Mesh[] = [];
  model.updateMatrixWorld(true);
  model.traverse((object) => {
    if ((object as Mesh).isMesh) meshes.push(object as Mesh);
  });
  const parts = meshes.map((mesh) => mesh.material);
  if (meshes.length < 2 || parts.some((m) => Array.isArray(m))) return model;
  const materials = [...new Set(parts as MeshStandardMaterial[])];
  if (!mergeable(materials)) return model;
  const toModel = new Matrix4().copy(model.matrixWorld).invert();
  const pieces: BufferGeometry[] = [];
  for (const mesh of meshes) {
    const material = mesh.material as MeshStandardMaterial;
    const k = materials.indexOf(material);
    const source = mesh.geometry.index ? mesh.geometry.toNonIndexed() : mesh.geometry.clone();
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', source.getAttribute('position'));
    geometry.setAttribute('normal', source.getAttribute('normal'));
    geometry.applyMatrix4(new Matrix4().multiplyMatrices(toModel, mesh.matrixWorld));
    const n = geometry.getAttribute('position').count;
    const colour = new Float32Array(3 * n);
    const uv = new Float32Array(2 * n);
    for (let v = 0; v < n; v++) {
      colour.set([material.color.r, material.color.g, material.color.b], 3 * v);
      uv.set([(k + 0.5) / materials.length, 0.5], 2 * v);
    }
    geometry.setAttribute('color', new BufferAttribute(colour, 3));
    geometry.setAttribute('uv', new BufferAttribute(uv, 2));
    pieces.push(geometry);
    if (material.side === DoubleSide) pieces.push(turnedOver(geometry));
  }
  const merged = mergeGeometries(pieces);
  if (!merged) return model;
  const table = new Float32Array(4 * materials.length);
  materials.forEach((m, k) => table.set([0, m.roughness, m.metalness, 1], 4 * k));
  const roughnessMetalness = new DataTexture(table, materials.length, 1, RGBAFormat, FloatType);
  roughnessMetalness.minFilter = roughnessMetalness.magFilter = NearestFilter;
  roughnessMetalness.needsUpdate = true;
  const material = materials[0].clone();
  material.name = 'Boat';
  material.color.setRGB(1, 1, 1);
  material.vertexColors = true;
  material.roughness = material.metalness = 1;
  material.roughnessMap = material.metalnessMap = roughnessMetalness;
  material.side = FrontSide;
  const boat = new Mesh(merged, material);
  boat.name = model.name || 'Boat model';
  return boat;
}
