import { BufferAttribute, BufferGeometry } from 'three';

/**
 * The seed's "básicamente, un plano": a flat square grid in the XZ plane, centred on the
 * origin, that the vertex shader displaces. Only positions: normals come from the shader.
 */
export function createGridGeometry(size: number, segments: number): BufferGeometry {
  const vertsPerSide = segments + 1;
  const positions = new Float32Array(vertsPerSide * vertsPerSide * 3);
  const step = size / segments;
  for (let j = 0; j < vertsPerSide; j++) {
    for (let i = 0; i < vertsPerSide; i++) {
      const o = (j * vertsPerSide + i) * 3;
      positions[o] = -size / 2 + i * step;
      positions[o + 2] = -size / 2 + j * step;
    }
  }
  const indices = new Uint32Array(segments * segments * 6);
  let k = 0;
  for (let j = 0; j < segments; j++) {
    for (let i = 0; i < segments; i++) {
      const a = j * vertsPerSide + i;
      const b = a + 1;
      const c = a + vertsPerSide;
      const d = c + 1;
      // Counter-clockwise seen from above (+y), so the front face looks up.
      indices[k++] = a;
      indices[k++] = c;
      indices[k++] = b;
      indices[k++] = b;
      indices[k++] = c;
      indices[k++] = d;
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setIndex(new BufferAttribute(indices, 1));
  return geometry;
}
