// The parts of three.js the 3D view (view3d.js) uses, bundled by esbuild at configure time
// (cmake/EmbedViewer.cmake) into one classic script defining the global THREE_VIEW.
export {
  AmbientLight, BufferAttribute, BufferGeometry, Color, DirectionalLight, DoubleSide, Group,
  LineBasicMaterial, LineDashedMaterial, LineSegments, Line, Mesh, MeshBasicMaterial,
  MeshLambertMaterial, PerspectiveCamera, Scene, SphereGeometry, Vector3, WebGLRenderer,
  Box3, CanvasTexture, Raycaster, Sprite, SpriteMaterial,
} from 'three';
export {OrbitControls} from 'three/examples/jsm/controls/OrbitControls.js';
