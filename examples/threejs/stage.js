// Penumbra's report stage (stage.json; reference/stage.hpp) as a three.js
// scene: three's own SpotLight (or DirectionalLight), shadow map and camera,
// and the boxes and the ground as three's geometry in a lit material.
//
// The stage is laid out in light-view space: the light at the origin
// looking down +z, x and y as the light sees them, which is left-handed.
// three's world is right-handed, so it holds the stage with z negated: a
// mirror image, which puts the spot light's shadow camera (looking down -z,
// up +y) exactly on light-view x and y.
import * as THREE from 'three';

const toWorld = (p) => new THREE.Vector3(p[0], p[1], -p[2]);

// `stage`: stage.json's object. Returns the renderer (drawing into
// `canvas`; with a reversed-Z depth buffer where `reversedDepthBuffer` and
// the browser has EXT_clip_control), the scene, the camera, the light (the
// stage's spot light, or its directional one where `directional`) and the
// meshes, each in `material`.
export function buildStage(stage, canvas, material,
                           {reversedDepthBuffer = false, directional = false} = {}) {
  const renderer =
      new THREE.WebGLRenderer({canvas, antialias: false, alpha: true, reversedDepthBuffer});
  renderer.setPixelRatio(1);
  renderer.setSize(stage.width, stage.height, false);
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = THREE.PCFShadowMap;
  renderer.setClearColor(0x000000, 0);

  const scene = new THREE.Scene();
  const {near, far, frustum_width: width} = stage.light;
  let light;
  if (directional) {
    // The shadow camera's square box is the directional light's width.
    light = new THREE.DirectionalLight(0xffffff, 3);
    const half = stage.directional.frustum_width / 2;
    Object.assign(light.shadow.camera, {left: -half, right: half, bottom: -half, top: half});
  } else {
    // The shadow camera's square frustum is Fw wide at the near plane n: a
    // cone of half-angle atan(Fw / 2n); no falloff with distance.
    light = new THREE.SpotLight(0xffffff, 3, 0, Math.atan(width / (2 * near)), 0, 0);
  }
  light.position.set(0, 0, 0);  // three puts lights at (0, 1, 0)
  light.target.position.set(0, 0, -1);
  light.castShadow = true;
  light.shadow.mapSize.set(stage.map_size, stage.map_size);
  light.shadow.camera.near = near;
  light.shadow.camera.far = far;
  light.shadow.camera.updateProjectionMatrix();
  scene.add(light, light.target, new THREE.AmbientLight(0xffffff, 0.25));

  const meshes = [];
  for (const [x0, y0, x1, y1, z0, z1] of stage.boxes) {
    const box = new THREE.Mesh(new THREE.BoxGeometry(x1 - x0, y1 - y0, z1 - z0), material);
    box.position.copy(toWorld([(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]));
    box.castShadow = true;
    box.receiveShadow = true;
    meshes.push(box);
  }
  const side = 2 * stage.ground.half_width;
  const ground = new THREE.Mesh(new THREE.PlaneGeometry(side, side), material);
  ground.position.copy(toWorld([0, 0, stage.ground.z]));  // facing the light, +z in three
  ground.receiveShadow = true;  // a receiver only, as in the library's own maps
  meshes.push(ground);
  scene.add(...meshes);

  const camera = new THREE.PerspectiveCamera(stage.camera.fov, stage.width / stage.height, 0.5, 100);
  camera.position.copy(toWorld(stage.camera.eye));
  camera.up.set(0, 0, 1);  // the stage's up is light-view -z
  camera.lookAt(toWorld(stage.camera.target));
  return {renderer, scene, camera, light, meshes};
}
