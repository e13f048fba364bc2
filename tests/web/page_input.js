// The page body and input of the scripted pages of the browser build (tests/web/file_io.html,
// bench/web/bench.html), served beside them: the app's canvas (1280 x 800, as index.html's) and its message
// line, and mouse events dispatched on the canvas, which emscripten's GLFW takes as a user's.
document.head.insertAdjacentHTML('beforeend',
  '<style>html, body { margin: 0; overflow: hidden; } canvas { display: block; width: 1280px; height: 800px; } ' +
  '#status { position: absolute; }</style>');
document.body.insertAdjacentHTML('beforeend',
  '<div id="status"></div><canvas id="canvas" width="1280" height="800" tabindex="0"></canvas>');
var canvas = document.getElementById('canvas');
function mouse(type, x, y) {
  canvas.dispatchEvent(new MouseEvent(type, {clientX: x, clientY: y, button: 0, buttons: type === 'mouseup' ? 0 : 1,
                                             bubbles: true, cancelable: true}));
}
