// The report's 3-D viewer: three.js r111 (Debian libjs-three, non-module build), one canvas per glb of
// results/pictures/ (each loaded from web/models/NAME.js, which calls clothbenchModel: file:// allows
// scripts, not fetch). Orbit and zoom (OrbitControls), cloth coloured per panel, by strain (_STRAIN) or
// by signed distance to the body (_DISTANCE); animated files (morph targets, the animation "walk") share
// one clock with play/pause and a time slider. The URL's hash sets a state for tests and links:
// #time=SECONDS (paused there), #colour=strain|distance|panels.
// For the browser test, <body> carries data-viewers-ready (models shown), data-canvases (where they are),
// data-time (the clip's clock [s]) and data-played (seconds played in all).
/* global THREE */
"use strict";

var CLOTHBENCH_MODELS = {};
function clothbenchModel(name, base64) {
  var text = atob(base64), bytes = new Uint8Array(text.length);
  for (var i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  CLOTHBENCH_MODELS[name] = bytes.buffer;
}

(function () {
  var viewers = [], clock = { time: 0, duration: 0, playing: true, last: null, played: 0 };

  function hashState() {
    var state = {};
    location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
      var p = kv.split("=");
      if (p[0]) state[p[0]] = decodeURIComponent(p[1] || "");
    });
    return state;
  }

  // colour ramps: strain 0 white -> 20 % red, compressed blue; distance inside red, 0 white -> 2 cm blue
  function strainColour(e, c) {
    if (e >= 0) { var s = Math.min(1, e / 0.2); c.setRGB(1, 1 - s, 1 - s); }
    else { var t = Math.min(1, -e / 0.1); c.setRGB(1 - t, 1 - t, 1); }
  }
  function distanceColour(d, c) {
    if (d < 0) c.setRGB(0.9, 0, 0);
    else { var s = Math.min(1, d / 0.02); c.setRGB(1 - s, 1 - 0.6 * s, 1); }
  }

  function setColourMode(v, mode) {
    v.cloth.forEach(function (mesh) {
      var g = mesh.geometry, field = mode === "strain" ? g.attributes._strain : g.attributes._distance;
      var m = mesh.material;
      if (mode === "panels" || !field) {
        m.vertexColors = THREE.NoColors;
        m.color.copy(mesh.userData.panelColour);
      } else {
        var colours = new Float32Array(3 * field.count), c = new THREE.Color();
        for (var i = 0; i < field.count; i++) {
          (mode === "strain" ? strainColour : distanceColour)(field.getX(i), c);
          colours[3 * i] = c.r; colours[3 * i + 1] = c.g; colours[3 * i + 2] = c.b;
        }
        g.setAttribute("color", new THREE.BufferAttribute(colours, 3));
        m.vertexColors = THREE.VertexColors;
        m.color.setRGB(1, 1, 1);
      }
      m.needsUpdate = true;
    });
  }

  function makeViewer(figure) {
    var name = figure.getAttribute("data-model"), box = figure.querySelector(".canvas");
    var data = CLOTHBENCH_MODELS[name];
    if (!data) { console.error("viewer: model " + name + " was not loaded (web/models/" + name + ".js)"); return; }
    var width = box.clientWidth || 400, height = box.clientHeight || 400;
    var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(width, height);
    renderer.setClearColor(0xf2f2f2);
    renderer.outputEncoding = THREE.sRGBEncoding;
    box.appendChild(renderer.domElement);
    var scene = new THREE.Scene();
    scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 0.9));
    var sun = new THREE.DirectionalLight(0xffffff, 0.7);
    sun.position.set(1, 2, 3);
    scene.add(sun);
    var camera = new THREE.PerspectiveCamera(35, width / height, 0.01, 100);
    var controls = new THREE.OrbitControls(camera, renderer.domElement);
    var v = { name: name, renderer: renderer, scene: scene, camera: camera, controls: controls, cloth: [], mixer: null };
    new THREE.GLTFLoader().parse(data, "", function (gltf) {
      var root = gltf.scene;
      scene.add(root);
      root.traverse(function (o) {
        if (!o.isMesh) return;
        o.frustumCulled = false;  // morph targets move the vertices beyond the base pose's bounds
        var animated = o.morphTargetInfluences && o.morphTargetInfluences.length;
        if (!animated && !o.geometry.attributes.normal) {
          o.geometry.computeVertexNormals();
          o.material.flatShading = false;
          o.material.needsUpdate = true;
        }
        if (o.geometry.attributes._strain) {
          o.material.side = THREE.DoubleSide;
          o.userData.panelColour = o.material.color.clone();
          v.cloth.push(o);
        }
      });
      // the camera on the body's front (glTF: y up, the body faces +z)
      // (of the base pose: the loader widens the bounds of morphed meshes by every target's offsets)
      var bounds = new THREE.Box3();
      root.traverse(function (o) {
        if (o.isMesh) bounds.union(new THREE.Box3().setFromBufferAttribute(o.geometry.attributes.position));
      });
      var centre = bounds.getCenter(new THREE.Vector3());
      var size = bounds.getSize(new THREE.Vector3());
      camera.position.set(centre.x, centre.y, centre.z + 1.4 * Math.max(size.y, size.x) / (2 * Math.tan(Math.PI * 35 / 360)));
      controls.target.copy(centre);
      controls.update();
      if (gltf.animations.length) {
        v.mixer = new THREE.AnimationMixer(root);
        v.mixer.clipAction(gltf.animations[0]).play();
        clock.duration = Math.max(clock.duration, gltf.animations[0].duration);
      }
      viewers.push(v);
      setColourMode(v, document.getElementById("colour-mode") ? document.getElementById("colour-mode").value : "panels");
      document.body.setAttribute("data-viewers-ready", String(viewers.length));
      // where each canvas is (CSS pixels, page coordinates) and whether it animates: for the browser test
      document.body.setAttribute("data-canvases", JSON.stringify(viewers.map(function (w) {
        var r = w.renderer.domElement.getBoundingClientRect();
        return { name: w.name, animated: !!w.mixer, x: r.left + window.scrollX, y: r.top + window.scrollY,
                 width: r.width, height: r.height };
      })));
    }, function (error) {
      console.error("viewer: " + name + ": " + error);
    });
  }

  function showTime() {
    var slider = document.getElementById("time"), label = document.getElementById("time-label");
    if (slider && clock.duration > 0) slider.value = String(Math.round(1000 * clock.time / clock.duration));
    if (label) label.textContent = clock.time.toFixed(2) + " s";
    document.body.setAttribute("data-time", clock.time.toFixed(3));
    document.body.setAttribute("data-played", clock.played.toFixed(3));
  }

  function frame(now) {
    if (clock.last !== null && clock.playing && clock.duration > 0) {
      clock.time = (clock.time + (now - clock.last) / 1000) % clock.duration;
      clock.played += (now - clock.last) / 1000;
    }
    clock.last = now;
    viewers.forEach(function (v) {
      if (v.mixer) v.mixer.setTime(clock.time);
      v.renderer.render(v.scene, v.camera);
    });
    showTime();
    requestAnimationFrame(frame);
  }

  window.addEventListener("load", function () {
    var figures = document.querySelectorAll(".viewer");
    if (!figures.length) return;
    var state = hashState(), select = document.getElementById("colour-mode");
    if (select && state.colour) select.value = state.colour;
    for (var i = 0; i < figures.length; i++) makeViewer(figures[i]);
    if (state.time !== undefined) { clock.time = parseFloat(state.time) || 0; clock.playing = false; }
    if (clock.duration > 0) clock.time = Math.min(clock.time, clock.duration);
    var play = document.getElementById("play"), slider = document.getElementById("time");
    if (play) {
      play.textContent = clock.playing ? "pause" : "play";
      play.addEventListener("click", function () {
        clock.playing = !clock.playing;
        play.textContent = clock.playing ? "pause" : "play";
      });
    }
    if (slider) slider.addEventListener("input", function () {
      clock.playing = false;
      if (play) play.textContent = "play";
      clock.time = clock.duration * parseInt(slider.value, 10) / 1000;
    });
    if (select) select.addEventListener("change", function () {
      viewers.forEach(function (v) { setColourMode(v, select.value); });
    });
    requestAnimationFrame(frame);
  });
})();
