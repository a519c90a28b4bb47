// One frame of a glTF file drawn by three.js, read back as sRGB bytes: the reference
// Velocity's glTF pipeline is measured against. render.py calls window.renderOracle(spec)
// over the DevTools protocol; spec (every field filled in by render.py):
//   model        URL of the .gltf/.glb (file://)
//   width, height
//   camera       {eye, target, up, yfov (degrees), znear, zfar}, or null: frame the model
//   frameYfov    the field of view (degrees) of the framing camera
//   lights       [{type: 'directional', direction, color, intensity}
//                 |{type: 'point', position, color, intensity, range}
//                 |{type: 'spot', position, direction, color, intensity, inner, outer (degrees), range}]
//   ambient      [r, g, b] linear, or null
//   fileLights   keep the file's KHR_lights_punctual lights (else they are removed)
//   tone         'none' | 'aces' | 'neutral';  exposure
//   background   [r, g, b] as the output's sRGB values / 255
//   antialias    the canvas's MSAA (off by default: every pixel one sample, like Velocity's ssaa 1)
//   shadows      null, or {mapSize, bias, normalBias}: every mesh casts and receives, every
//                light of `lights` casts through a PCF-filtered shadow map fitted to the model
// Returns {width, height, rgba: base64 of the RGBA bytes, top row first, camera, renderer, three}.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

// 'none' is LinearToneMapping so that the exposure still applies (three skips it with
// NoToneMapping); at exposure 1 the two are the same: colour, clamped, then sRGB.
const TONE_MAPPING = {
  none: THREE.LinearToneMapping,
  aces: THREE.ACESFilmicToneMapping,
  neutral: THREE.NeutralToneMapping,
};

function vec(a) { return new THREE.Vector3(a[0], a[1], a[2]); }

// Lights as KHR_lights_punctual defines them and GLTFLoader builds them: intensities in
// lux (directional) and candela (point, spot), inverse-square falloff (decay 2), colours
// linear; range 0 is unbounded. A directional or spot light shines along `direction`.
function makeLight(spec) {
  const color = new THREE.Color().setRGB(...spec.color, THREE.LinearSRGBColorSpace);
  let light;
  if (spec.type === 'directional') {
    light = new THREE.DirectionalLight(color, spec.intensity);
    light.position.copy(vec(spec.direction).normalize().negate());
    light.target.position.set(0, 0, 0);
  } else if (spec.type === 'point') {
    light = new THREE.PointLight(color, spec.intensity, spec.range, 2);
    light.position.copy(vec(spec.position));
  } else if (spec.type === 'spot') {
    const outer = THREE.MathUtils.degToRad(spec.outer);
    const inner = THREE.MathUtils.degToRad(spec.inner);
    // GLTFLoader's mapping of innerConeAngle/outerConeAngle onto angle/penumbra.
    light = new THREE.SpotLight(color, spec.intensity, spec.range, outer, 1 - inner / outer, 2);
    light.position.copy(vec(spec.position));
    light.target.position.copy(vec(spec.position).add(vec(spec.direction)));
  } else {
    throw new Error(`unknown light type '${spec.type}'`);
  }
  return light;
}

// A camera that sees the whole model: along -Z towards its bounding sphere's centre.
function frameCamera(object, aspect, yfov) {
  const sphere = new THREE.Box3().setFromObject(object).getBoundingSphere(new THREE.Sphere());
  const r = Math.max(sphere.radius, 1e-6);
  // The narrower of the vertical and horizontal fields of view must hold the sphere.
  const half = Math.atan(Math.tan(THREE.MathUtils.degToRad(yfov) / 2) * Math.min(aspect, 1));
  const distance = 1.1 * r / Math.sin(half);
  const c = sphere.center;
  return { eye: [c.x, c.y, c.z + distance], target: [c.x, c.y, c.z], up: [0, 1, 0],
           yfov, znear: Math.max(distance - 2 * r, distance * 1e-3), zfar: distance + 2 * r };
}

// Shadow maps that see the whole model: three's defaults assume a scene a few units
// across (a directional light's box is +-5, the near plane of the others 0.5).
function castShadows(light, sphere, shadows) {
  light.castShadow = true;
  light.shadow.mapSize.set(shadows.mapSize, shadows.mapSize);
  light.shadow.bias = shadows.bias;
  light.shadow.normalBias = shadows.normalBias;
  const c = sphere.center;
  const r = Math.max(sphere.radius, 1e-6);
  const camera = light.shadow.camera;
  if (light.isDirectionalLight) {
    // Same direction, moved back so that the model lies between 1 and 3 radii in front.
    const towardsLight = light.position.clone().sub(light.target.position).normalize();
    light.position.copy(c).addScaledVector(towardsLight, 2 * r);
    light.target.position.copy(c);
    Object.assign(camera, { left: -r, right: r, top: r, bottom: -r, near: 0.5 * r, far: 3.5 * r });
  } else {
    const reach = light.position.distanceTo(c) + r;
    camera.near = reach * 1e-3;
    camera.far = reach;
  }
  camera.updateProjectionMatrix();
}

function base64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

window.renderOracle = async function (spec) {
  const canvas = document.createElement('canvas');
  let renderer;
  try {
    // preserveDrawingBuffer: the frame stays readable after render() returns.
    renderer = new THREE.WebGLRenderer({ canvas, antialias: spec.antialias, alpha: false,
                                         preserveDrawingBuffer: true });
  } catch (e) {
    throw new Error(`WebGL is not available: ${e.message}`);
  }
  renderer.setPixelRatio(1);
  renderer.setSize(spec.width, spec.height, false);
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.toneMapping = TONE_MAPPING[spec.tone];
  renderer.toneMappingExposure = spec.exposure;

  let gltf;
  try {
    gltf = await new GLTFLoader().loadAsync(spec.model);
  } catch (e) {
    throw new Error(`GLTFLoader could not load it: ${e.message || e}`);
  }
  const model = gltf.scene || gltf.scenes[0];
  if (!model) throw new Error('the file has no scene');
  if (!spec.fileLights) {
    const fileLights = [];
    model.traverse((o) => { if (o.isLight) fileLights.push(o); });
    fileLights.forEach((l) => l.removeFromParent());
  }

  const scene = new THREE.Scene();
  scene.background = new THREE.Color().setRGB(...spec.background, THREE.SRGBColorSpace);
  scene.add(model);
  const bounds = new THREE.Box3().setFromObject(model).getBoundingSphere(new THREE.Sphere());
  if (spec.shadows) {
    renderer.shadowMap.enabled = true;
    renderer.shadowMap.type = THREE.PCFShadowMap;
    // Every face blocks light, as in the world: three's default draws only the faces
    // turned away from the light into the map (less acne on closed meshes), so that an
    // open one-sided surface, a glTF leaf or quad, would cast no shadow.
    model.traverse((o) => {
      if (!o.isMesh) return;
      o.castShadow = o.receiveShadow = true;
      for (const m of Array.isArray(o.material) ? o.material : [o.material]) m.shadowSide = THREE.DoubleSide;
    });
  }
  for (const l of spec.lights) {
    const light = makeLight(l);
    if (spec.shadows) castShadows(light, bounds, spec.shadows);
    scene.add(light);
    if (light.target) scene.add(light.target);
  }
  if (spec.ambient) scene.add(new THREE.AmbientLight(new THREE.Color().setRGB(...spec.ambient, THREE.LinearSRGBColorSpace), 1));

  const aspect = spec.width / spec.height;
  const cam = spec.camera || frameCamera(model, aspect, spec.frameYfov);
  const camera = new THREE.PerspectiveCamera(cam.yfov, aspect, cam.znear, cam.zfar);
  camera.position.copy(vec(cam.eye));
  camera.up.copy(vec(cam.up));
  camera.lookAt(vec(cam.target));
  camera.updateMatrixWorld();

  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const rgba = new Uint8Array(spec.width * spec.height * 4);
  gl.readPixels(0, 0, spec.width, spec.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
  const glError = gl.getError();
  if (glError !== gl.NO_ERROR) throw new Error(`readPixels failed: GL error 0x${glError.toString(16)}`);
  // readPixels returns the bottom row first; images are written top row first.
  const rowBytes = spec.width * 4;
  const flipped = new Uint8Array(rgba.length);
  for (let y = 0; y < spec.height; y++) {
    flipped.set(rgba.subarray((spec.height - 1 - y) * rowBytes, (spec.height - y) * rowBytes), y * rowBytes);
  }
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const result = { width: spec.width, height: spec.height, rgba: base64(flipped), camera: cam,
                   renderer: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
                   three: THREE.REVISION };
  renderer.dispose();
  renderer.forceContextLoss();
  return result;
};
