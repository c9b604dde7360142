/**
 * three.js's own ocean example (examples/webgl_shaders_ocean.html), rebuilt for
 * `npm run bench`: the installed `three` package ships Water.js and Sky.js but neither that
 * page nor its textures/waternormals.jpg. Everything drawn is the example's, with its
 * parameters: WebGLRenderer with a HalfFloat output buffer and ACES tone mapping at exposure
 * 0.1, one UnrealBloomPass(1.5, 0.4, 0.85) with threshold 0, strength 0.1, radius 0 set as a
 * renderer effect, camera fov 55, near 1, far 20000 at (30, 30, 100) looking at (0, 10, 0)
 * (the OrbitControls target), a 10 km PlaneGeometry with Water (512² mirror, sun colour
 * white, water colour 0x001e0f, distortion scale 3.7), Sky scaled 10000 (turbidity 10,
 * rayleigh 2, Mie 0.005 / 0.8, clouds 0.4 / 0.5 / 0.5), the sun at elevation 2°, azimuth
 * 180°, a PMREM environment of the sky, and the 30 m MeshStandardMaterial box.
 * What differs, and why:
 * - The water normal map is made here (a tiling, 1024² RGB normal map of summed sine
 *   waves, mipmapped and repeating like the loaded JPEG) instead of loaded: the JPEG is not
 *   in the npm package. Its content does not change the cost: the shader samples it four
 *   times per pixel either way.
 * - Time is fixed (t = 10 s) instead of read from the clock, so every run draws the same
 *   picture; there are no OrbitControls, Stats or GUI, which draw nothing in the canvas.
 * - `?bloom=0` draws the example as it was before three.js added bloom and clouds (Water +
 *   Sky, exposure 1), the form most often compared with.
 */
import * as THREE from 'three';
import { Water } from 'three/addons/objects/Water.js';
import { Sky } from 'three/addons/objects/Sky.js';
import { UnrealBloomPass } from 'three/addons/postprocessing/UnrealBloomPass.js';

declare global {
  interface Window {
    threejsOcean: {
      bloom: boolean;
      renderFrame(): void;
      stats(): { drawCalls: number; triangles: number };
      canvas(): [number, number];
    };
  }
}

const TIME_SECONDS = 10;
const NORMAL_MAP_SIZE = 1024;

/** A tiling normal map: the gradient of a sum of whole-period sine waves, encoded as 0.5 + 0.5 n. */
function waterNormalsTexture(size: number): THREE.DataTexture {
  const data = new Uint8Array(size * size * 4);
  // Wave vectors in whole cycles per tile, so the map repeats without a seam.
  const waves: [number, number, number, number][] = [
    [3, 1, 0.35, 0.0],
    [-2, 5, 0.25, 1.3],
    [7, -4, 0.15, 2.1],
    [11, 9, 0.1, 0.7],
    [-17, 6, 0.06, 4.0],
    [23, -19, 0.04, 5.2],
  ];
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      let dx = 0;
      let dy = 0;
      for (const [kx, ky, amplitude, phase] of waves) {
        const c = amplitude * Math.cos((2 * Math.PI * (kx * i + ky * j)) / size + phase);
        dx += c * kx;
        dy += c * ky;
      }
      const scale = 0.08;
      const n = new THREE.Vector3(-dx * scale, -dy * scale, 1).normalize();
      const o = 4 * (j * size + i);
      data[o] = Math.round(255 * (0.5 + 0.5 * n.x));
      data[o + 1] = Math.round(255 * (0.5 + 0.5 * n.y));
      data[o + 2] = Math.round(255 * (0.5 + 0.5 * n.z));
      data[o + 3] = 255;
    }
  }
  const texture = new THREE.DataTexture(data, size, size, THREE.RGBAFormat);
  // As TextureLoader's texture: mipmapped, trilinear, and set to repeat by the example.
  texture.generateMipmaps = true;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
  texture.needsUpdate = true;
  return texture;
}

const bloom = new URLSearchParams(location.search).get('bloom') !== '0';
const container = document.getElementById('container') as HTMLElement;

const renderer = new THREE.WebGLRenderer(bloom ? { outputBufferType: THREE.HalfFloatType } : {});
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
renderer.toneMapping = THREE.ACESFilmicToneMapping;
renderer.toneMappingExposure = bloom ? 0.1 : 1;
container.appendChild(renderer.domElement);

if (bloom) {
  const bloomPass = new UnrealBloomPass(new THREE.Vector2(window.innerWidth, window.innerHeight), 1.5, 0.4, 0.85);
  bloomPass.threshold = 0;
  bloomPass.strength = 0.1;
  bloomPass.radius = 0;
  renderer.setEffects([bloomPass]);
}

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(55, window.innerWidth / window.innerHeight, 1, 20000);
camera.position.set(30, 30, 100);
camera.lookAt(0, 10, 0);

const sun = new THREE.Vector3();
const water = new Water(new THREE.PlaneGeometry(10000, 10000), {
  textureWidth: 512,
  textureHeight: 512,
  waterNormals: waterNormalsTexture(NORMAL_MAP_SIZE),
  sunDirection: new THREE.Vector3(),
  sunColor: 0xffffff,
  waterColor: 0x001e0f,
  distortionScale: 3.7,
  fog: scene.fog !== undefined,
});
water.rotation.x = -Math.PI / 2;
scene.add(water);

const sky = new Sky();
sky.scale.setScalar(10000);
scene.add(sky);
const skyUniforms = sky.material.uniforms;
skyUniforms['turbidity'].value = 10;
skyUniforms['rayleigh'].value = 2;
skyUniforms['mieCoefficient'].value = 0.005;
skyUniforms['mieDirectionalG'].value = 0.8;
if (bloom) {
  skyUniforms['cloudCoverage'].value = 0.4;
  skyUniforms['cloudDensity'].value = 0.5;
  skyUniforms['cloudElevation'].value = 0.5;
} else {
  // Before the clouds were added to Sky, the example had none.
  skyUniforms['cloudCoverage'].value = 0;
}

const pmremGenerator = new THREE.PMREMGenerator(renderer);
const sceneEnv = new THREE.Scene();
sun.setFromSphericalCoords(1, THREE.MathUtils.degToRad(90 - 2), THREE.MathUtils.degToRad(180));
sky.material.uniforms['sunPosition'].value.copy(sun);
water.material.uniforms['sunDirection'].value.copy(sun).normalize();
sceneEnv.add(sky);
scene.environment = pmremGenerator.fromScene(sceneEnv).texture;
scene.add(sky);

const mesh = new THREE.Mesh(new THREE.BoxGeometry(30, 30, 30), new THREE.MeshStandardMaterial({ roughness: 0 }));
scene.add(mesh);

mesh.position.y = Math.sin(TIME_SECONDS) * 20 + 5;
mesh.rotation.x = TIME_SECONDS * 0.5;
mesh.rotation.z = TIME_SECONDS * 0.51;
water.material.uniforms['time'].value = TIME_SECONDS;
skyUniforms['time'].value = TIME_SECONDS;

const pixel = new Uint8Array(4);
const gl = renderer.getContext();

/** The benchmark's handle: one frame, ended like Oceano's by a one-pixel readPixels that waits for the GPU. */
window.threejsOcean = {
  bloom,
  renderFrame(): void {
    renderer.render(scene, camera);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  },
  stats: () => ({ drawCalls: renderer.info.render.calls, triangles: renderer.info.render.triangles }),
  canvas: (): [number, number] => [renderer.domElement.width, renderer.domElement.height],
};
