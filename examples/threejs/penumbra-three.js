// Penumbra's soft shadows in three.js's own materials: a SpotLight's or a
// DirectionalLight's shadow term replaced by a variant's essl300 function
// form, penumbra_visibility(), reading three's own shadow map (README.md). Everything this
// module binds comes from index.json: the function's file, its textures and
// their sampler states, and its parameter block.
//
// three.js sets sampling state on the texture and binds no uniform blocks
// for its built-in materials, while the function reads the one depth
// texture twice (raw depths and hardware comparisons) and its parameters
// from a block. So this module keeps its bindings where three never looks:
// the top texture units, each with a WebGL 2 sampler object, and the last
// uniform-buffer binding point.
import * as THREE from 'three';

const TARGET = 'essl300';

// The shadow term of a `kind` of light ('spot' or 'directional') in three
// r187's lights_fragment_begin chunk.
function threeShadowTerm(kind) {
  const coord = kind === 'spot' ? 'vSpotLightCoord' : 'vDirectionalShadowCoord';
  return 'directLight.color *= ( directLight.visible && receiveShadow ) ? ' +
         `getShadow( ${kind}ShadowMap[ i ], ${kind}LightShadow.shadowMapSize, ` +
         `${kind}LightShadow.shadowIntensity, ${kind}LightShadow.shadowBias, ` +
         `${kind}LightShadow.shadowRadius, ${coord}[ i ] ) : 1.0;`;
}

// index.json's record of `name`'s function form for essl300, or an error
// naming what is missing.
function functionForm(index, name) {
  const variant = index.variants.find((v) => v.name === name);
  if (!variant) throw new Error(`index.json: no variant named '${name}'`);
  const form = variant.function && variant.function[TARGET];
  if (!form) {
    throw new Error(`index.json: /variants/${name}/function has no ${TARGET} form ` +
                    '(every technique but screen_blur and the back-projections, built for ' +
                    'essl300, has one)');
  }
  const reflection = index.reflections[form.reflection];
  if (reflection.extensions && reflection.extensions.length) {
    throw new Error(`${form.file}: needs GLSL extensions (${reflection.extensions.join(', ')}), ` +
                    'which three.js materials cannot enable');
  }
  if (reflection.frag.textures.some((t) => t.name === 'penumbra_shadow_minmax')) {
    throw new Error(`${form.file}: reads the min-max mip of the map, which this module does ` +
                    'not build; it binds three\'s shadow map alone (hard, pcf_grid, pcf_poisson, pcss)');
  }
  const encoding = variant.keys.map_encoding || 'linear';
  return {variant, file: form.file, reflection, encoding};
}

function createSampler(gl, state) {
  const sampler = gl.createSampler();
  const filter = state.filter === 'linear' ? gl.LINEAR : gl.NEAREST;
  gl.samplerParameteri(sampler, gl.TEXTURE_MIN_FILTER, filter);
  gl.samplerParameteri(sampler, gl.TEXTURE_MAG_FILTER, filter);
  gl.samplerParameteri(sampler, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.samplerParameteri(sampler, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  const compare = {none: null, less_equal: gl.LEQUAL, greater_equal: gl.GEQUAL}[state.comparison];
  if (compare === undefined) throw new Error(`sampler comparison '${state.comparison}' is not known`);
  gl.samplerParameteri(sampler, gl.TEXTURE_COMPARE_MODE,
                       compare === null ? gl.NONE : gl.COMPARE_REF_TO_TEXTURE);
  if (compare !== null) gl.samplerParameteri(sampler, gl.TEXTURE_COMPARE_FUNC, compare);
  return sampler;
}

// What PenumbraSpotShadow and PenumbraDirectionalShadow share: `kind` is
// 'spot' or 'directional', `lightIndex` the light's place among three's
// shadow-casting lights of that kind, `expected` the map_encoding of three's
// map for it, `lightSize` ShadowParams' L.
class PenumbraShadow {
  constructor(renderer, light, kind, {index, variant, source, lightIndex, expected, lightSize,
                                      bias, filterRadiusUV}) {
    this.form = functionForm(index, variant);
    if (this.form.encoding !== expected) {
      throw new Error(`${variant}: map_encoding '${this.form.encoding}' does not match three's ` +
                      `${kind}-light map (${expected}); build the variant with "map_encoding": "${expected}"`);
    }
    this.renderer = renderer;
    this.light = light;
    this.kind = kind;
    this.source = source;
    this.lightIndex = lightIndex;
    this.options = {lightSize, bias, filterRadiusUV};
    // The fragment's call: the light clip position, and the pixel where the
    // variant rotates its samples per pixel (the `rotation` key).
    this.visibility = /vec2\s+pixel/.test(this.form.reflection.signature)
                          ? 'penumbra_visibility(penumbraLightClip, floor(gl_FragCoord.xy))'
                          : 'penumbra_visibility(penumbraLightClip)';

    const gl = renderer.getContext();
    this.gl = gl;
    const frag = this.form.reflection.frag;
    if ((frag.uniforms || []).length || (frag.blocks || []).length !== 1) {
      throw new Error(`${this.form.file}: penumbra-three binds one parameter block and no loose uniforms`);
    }
    this.block = frag.blocks[0];
    this.buffer = gl.createBuffer();
    this.blockData = new Float32Array(this.block.size / 4);
    this.bindingPoint = gl.getParameter(gl.MAX_UNIFORM_BUFFER_BINDINGS) - 1;
    const units = gl.getParameter(gl.MAX_TEXTURE_IMAGE_UNITS);
    this.textures = frag.textures.map((texture, k) => ({
      name: texture.name,
      unit: units - frag.textures.length + k,
      sampler: createSampler(gl, texture.sampler),
    }));
    this.lightMatrix = new THREE.Matrix4();
    this.configured = new WeakSet();  // the GL programs whose bindings are set
    this.materials = new Set();
  }

  // Patches `material` (a lit built-in material: Lambert, Phong, Standard,
  // Physical) so that this light's shadow term is penumbra_visibility().
  // Returns the material.
  apply(material) {
    const chunk = THREE.ShaderChunk.lights_fragment_begin;
    const term = threeShadowTerm(this.kind);
    if (!chunk.includes(term)) {
      throw new Error(`three.js ${THREE.REVISION}'s lights_fragment_begin has no ${this.kind} ` +
                      'shadow term penumbra-three knows (it is written for r187)');
    }
    const lights = chunk.replace(term,
      `#if UNROLLED_LOOP_INDEX == ${this.lightIndex}\n` +
      'directLight.color *= ( directLight.visible && receiveShadow ) ? ' +
      `mix( 1.0, ${this.visibility}, ${this.kind}LightShadow.shadowIntensity ) : 1.0;\n` +
      `#else\n${term}\n#endif`);
    const lightMatrix = this.lightMatrix;
    const source = this.source;
    const previous = material.onBeforeCompile;
    material.onBeforeCompile = (shader, renderer) => {
      previous.call(material, shader, renderer);
      shader.uniforms.penumbraLightMatrix = {value: lightMatrix};
      shader.vertexShader = shader.vertexShader
        .replace('void main() {',
                 'uniform mat4 penumbraLightMatrix;\nout vec4 penumbraLightClip;\nvoid main() {')
        .replace('#include <project_vertex>',
                 '#include <project_vertex>\n' +
                 '\tvec4 penumbraWorld = vec4( transformed, 1.0 );\n' +
                 '\t#ifdef USE_BATCHING\n\tpenumbraWorld = batchingMatrix * penumbraWorld;\n\t#endif\n' +
                 '\t#ifdef USE_INSTANCING\n\tpenumbraWorld = instanceMatrix * penumbraWorld;\n\t#endif\n' +
                 '\tpenumbraLightClip = penumbraLightMatrix * modelMatrix * penumbraWorld;');
      shader.fragmentShader = shader.fragmentShader
        .replace('void main() {', `in vec4 penumbraLightClip;\n${source}\nvoid main() {`)
        .replace('#include <lights_fragment_begin>', lights);
    };
    const key = material.customProgramCacheKey;
    material.customProgramCacheKey = () => `${key.call(material)}|penumbra:${this.form.file}`;
    const before = material.onBeforeRender;
    material.onBeforeRender = (...args) => {
      before.apply(material, args);
      this.bind(material);
    };
    material.needsUpdate = true;
    this.materials.add(material);
    return material;
  }

  // Compiles the programs of every patched material in `scene` for drawing
  // into `target` (null: the canvas) and sets their bindings. three compiles
  // a program per target kind (colour space, tone mapping), so call it for
  // each kind you draw into before the first draw, and again after a change
  // that makes three recompile: a program three compiles during a draw has
  // no bindings for that draw.
  prepare(scene, camera, target = null) {
    const previous = this.renderer.getRenderTarget();
    this.renderer.setRenderTarget(target);
    this.renderer.compile(scene, camera);
    this.renderer.setRenderTarget(previous);
    for (const material of this.materials) this.configure(material);
  }

  // The parameter block for three's shadow camera as it is now
  // (docs/shader-interface.md, "ShadowParams").
  parameters() {
    const shadow = this.light.shadow;
    const camera = shadow.camera;
    const width = shadow.mapSize.x, height = shadow.mapSize.y;
    const near = camera.near, far = camera.far;
    const frustumWidth = this.frustumWidth(camera);
    const size = this.renderer.getDrawingBufferSize(new THREE.Vector2());
    const {lightSize, bias, filterRadiusUV} = this.options;
    return {
      shadow_map_size: [width, height, 1 / width, 1 / height],
      light: [lightSize, frustumWidth, near, lightSize / frustumWidth],
      sampling: [filterRadiusUV ?? 2 / width, bias, 1 / far, far],
      screen_size: [size.x, size.y, 1 / size.x, 1 / size.y],
      source_size: [0, 0, 0, 0],
      minmax_info: [0, 0, 0, 0],
    };
  }

  // Before each draw of a patched material: the light's matrix, the block
  // and the textures, for three's map as the shadow pass just drew it.
  bind(material) {
    const gl = this.gl;
    const shadow = this.light.shadow;
    this.lightMatrix.multiplyMatrices(shadow.camera.projectionMatrix, shadow.camera.matrixWorldInverse);
    const values = this.parameters();
    for (const member of this.block.members) {
      this.blockData.set(values[member.parameter], member.offset / 4);
    }
    gl.bindBuffer(gl.UNIFORM_BUFFER, this.buffer);
    gl.bufferData(gl.UNIFORM_BUFFER, this.blockData, gl.DYNAMIC_DRAW);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, this.bindingPoint, this.buffer);
    const map = shadow.map && shadow.map.depthTexture;
    const texture = map && this.renderer.properties.get(map).__webglTexture;
    if (!texture) return;  // no shadow pass has drawn the map yet: nothing to bind
    for (const {unit, sampler} of this.textures) {
      this.renderer.state.bindTexture(gl.TEXTURE_2D, texture, gl.TEXTURE0 + unit);
      gl.bindSampler(unit, sampler);
    }
    this.configure(material);
  }

  // Points every program three compiled for `material` at this module's
  // units and binding point.
  configure(material) {
    const programs = this.renderer.properties.get(material).programs;
    if (!programs) return;
    const gl = this.gl;
    for (const {program} of programs.values()) {
      if (this.configured.has(program)) continue;
      this.renderer.state.useProgram(program);
      for (const {name, unit} of this.textures) {
        const location = gl.getUniformLocation(program, name);
        if (location !== null) gl.uniform1i(location, unit);
      }
      const block = gl.getUniformBlockIndex(program, this.block.name);
      if (block !== gl.INVALID_INDEX) gl.uniformBlockBinding(program, block, this.bindingPoint);
      this.configured.add(program);
    }
  }

  dispose() {
    for (const {unit, sampler} of this.textures) {
      this.gl.bindSampler(unit, null);
      this.gl.deleteSampler(sampler);
    }
    this.gl.deleteBuffer(this.buffer);
  }
}

export class PenumbraSpotShadow extends PenumbraShadow {
  // `light`: a THREE.SpotLight that casts shadows, the `spotIndex`-th of
  // three's shadow-casting spot lights (0 for the first or only one).
  // `index` is the library's parsed index.json, `variant` a variant name,
  // `source` the text of its essl300 function form file. Options:
  //   lightWorldSize: half-width of the square area light, world units
  //   bias: subtracted from the receiver's light-view depth (world units)
  //   filterRadiusUV: pcf_poisson's radius in map uv (default 2 texels)
  constructor(renderer, light, {index, variant, source, spotIndex = 0, lightWorldSize,
                                bias = 0, filterRadiusUV} = {}) {
    if (!light || !light.isSpotLight || !light.castShadow) {
      throw new Error('PenumbraSpotShadow: the light must be a THREE.SpotLight with castShadow');
    }
    if (!(lightWorldSize > 0)) throw new Error('PenumbraSpotShadow: lightWorldSize must be > 0');
    const reversed = renderer.capabilities.reversedDepthBuffer === true;
    super(renderer, light, 'spot', {
      index, variant, source, lightIndex: spotIndex, lightSize: lightWorldSize, bias,
      filterRadiusUV, expected: reversed ? 'perspective_reversed' : 'perspective'});
  }

  // Fw = 2 n tan(fov / 2) of the square perspective shadow camera.
  frustumWidth(camera) {
    if (Math.abs(camera.aspect - 1) > 1e-6) {
      throw new Error('PenumbraSpotShadow: the shadow camera must be square (aspect 1)');
    }
    return 2 * camera.near * Math.tan(THREE.MathUtils.DEG2RAD * 0.5 * camera.fov) / camera.zoom;
  }
}

export class PenumbraDirectionalShadow extends PenumbraShadow {
  // `light`: a THREE.DirectionalLight that casts shadows, the
  // `directionalIndex`-th of three's shadow-casting directional lights.
  // Options as PenumbraSpotShadow's, but for the light's size:
  //   angularRadius: half the angle the light spans (radians; the sun's is
  //   about 0.0047), a square of directions for PCSS and the reference
  constructor(renderer, light, {index, variant, source, directionalIndex = 0, angularRadius,
                                bias = 0, filterRadiusUV} = {}) {
    if (!light || !light.isDirectionalLight || !light.castShadow) {
      throw new Error('PenumbraDirectionalShadow: the light must be a THREE.DirectionalLight ' +
                      'with castShadow');
    }
    if (!(angularRadius > 0 && angularRadius < Math.PI / 2)) {
      throw new Error('PenumbraDirectionalShadow: angularRadius must be in (0, pi / 2) radians');
    }
    if (renderer.capabilities.reversedDepthBuffer === true) {
      throw new Error('PenumbraDirectionalShadow: a reversed-Z renderer draws a reversed ' +
                      'orthographic map, which has no map_encoding yet');
    }
    super(renderer, light, 'directional', {
      index, variant, source, lightIndex: directionalIndex, lightSize: Math.tan(angularRadius),
      bias, filterRadiusUV, expected: 'orthographic'});
  }

  // The orthographic shadow camera's width, right - left over its zoom.
  frustumWidth(camera) {
    const {left, right, bottom, top} = camera;
    if (Math.abs(left + right) > 1e-6 * right || Math.abs(bottom + top) > 1e-6 * top ||
        Math.abs((right - left) - (top - bottom)) > 1e-6 * (right - left)) {
      throw new Error('PenumbraDirectionalShadow: the shadow camera must be square and centred ' +
                      '(left = -right, bottom = -top, right - left = top - bottom)');
    }
    return (right - left) / camera.zoom;
  }
}
