// cloud_view.js - the rotatable 3-D sample clouds of a ggx report page.
// Needs three.js r111's classic build (global THREE) and its OrbitControls,
// loaded before this file.  ggxCloud(id, cloud) fills the element `id`:
// the points on the unit sphere (o or m, switched by the buttons), coloured
// by log pdf, with the normal (+z) and the view drawn as arrows.  Points come
// base64-encoded: directions as little-endian int16 (x 32767), colours as one
// byte each (0: no density, 1..255: log pdf from low to high).  The view is
// drawn on demand (after a drag), not in a loop.  Without WebGL the element
// says so in place of the view.
(function () {
  "use strict";

  var anchors = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];  // viridis

  function colourOf(t) {
    var x = Math.min(Math.max(t, 0), 1) * (anchors.length - 1);
    var k = Math.min(Math.floor(x), anchors.length - 2), f = x - k;
    return anchors[k].map(function (c, j) { return (c + f * (anchors[k + 1][j] - c)) / 255; });
  }

  function bytesOf(text) {
    var raw = atob(text), bytes = new Uint8Array(raw.length);
    for (var j = 0; j < raw.length; ++j)
      bytes[j] = raw.charCodeAt(j);
    return bytes;
  }

  function pointsOf(directions, colours) {
    var xyz = new Int16Array(bytesOf(directions).buffer), shade = bytesOf(colours);
    var position = new Float32Array(xyz.length), colour = new Float32Array(xyz.length);
    for (var j = 0; j < shade.length; ++j) {
      var rgb = shade[j] === 0 ? [0.6, 0.6, 0.6] : colourOf((shade[j] - 1) / 254);
      for (var c = 0; c < 3; ++c) {
        position[3 * j + c] = xyz[3 * j + c] / 32767;
        colour[3 * j + c] = rgb[c];
      }
    }
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
    geometry.setAttribute("color", new THREE.BufferAttribute(colour, 3));
    return new THREE.Points(geometry, new THREE.PointsMaterial({size: 2.5, sizeAttenuation: false,
                                                                 vertexColors: THREE.VertexColors}));
  }

  function webglWorks() {
    try {
      var canvas = document.createElement("canvas");
      return !!(window.WebGLRenderingContext && (canvas.getContext("webgl") || canvas.getContext("experimental-webgl")));
    } catch (e) {
      return false;
    }
  }

  // The unit sphere as faint lines, the horizon, the normal and the view.
  function frame(cloud) {
    var group = new THREE.Group();
    var sphere = new THREE.LineSegments(new THREE.WireframeGeometry(new THREE.SphereBufferGeometry(1, 24, 12)),
                                        new THREE.LineBasicMaterial({color: 0xc8c8c8, transparent: true, opacity: 0.35}));
    sphere.rotation.x = Math.PI / 2;  // its poles on z
    group.add(sphere);
    var horizon = new THREE.LineLoop(new THREE.CircleGeometry(1, 96), new THREE.LineBasicMaterial({color: 0x888888}));
    horizon.geometry.vertices.shift();  // the circle without its centre
    group.add(horizon);
    var origin = new THREE.Vector3(0, 0, 0);
    group.add(new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), origin, 1.35, 0x222222, 0.1, 0.05));
    var view = new THREE.Vector3(cloud.view[0], cloud.view[1], cloud.view[2]).normalize();
    group.add(new THREE.ArrowHelper(view, origin, 1.35, 0xd62728, 0.1, 0.05));
    return group;
  }

  function say(holder, text) {
    var note = document.createElement("p");
    note.className = "no-webgl";
    note.textContent = text;
    holder.querySelector(".view").appendChild(note);
  }

  window.ggxCloud = function (id, cloud) {
    var holder = document.getElementById(id);
    if (typeof THREE === "undefined" || typeof THREE.OrbitControls === "undefined") {
      say(holder, "The 3-D view needs three.js beside this page (three/three.min.js); the .npy and .ply files hold the same points.");
      return;
    }
    if (!webglWorks()) {
      say(holder, "This browser has no WebGL, so the 3-D view cannot be drawn; the .npy and .ply files hold the same points.");
      return;
    }
    var view = holder.querySelector(".view");
    var width = view.clientWidth || 420, height = view.clientHeight || 360;
    var renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(width, height);
    renderer.setClearColor(0xffffff, 1);
    view.appendChild(renderer.domElement);
    var camera = new THREE.PerspectiveCamera(30, width / height, 0.1, 100);
    camera.up.set(0, 0, 1);
    camera.position.set(3.1, -3.8, 2.5);
    var scene = new THREE.Scene();
    scene.add(frame(cloud));
    var clouds = {o: pointsOf(cloud.o, cloud.o_colour), m: pointsOf(cloud.m, cloud.m_colour)};
    var shown = clouds.o;
    scene.add(shown);
    var controls = new THREE.OrbitControls(camera, renderer.domElement);
    var draw = function () { renderer.render(scene, camera); };
    controls.addEventListener("change", draw);
    holder.querySelectorAll("button[data-show]").forEach(function (button) {
      button.addEventListener("click", function () {
        scene.remove(shown);
        shown = clouds[button.dataset.show];
        scene.add(shown);
        holder.querySelectorAll("button[data-show]").forEach(function (b) { b.classList.toggle("on", b === button); });
        draw();
      });
    });
    draw();
  };
})();
