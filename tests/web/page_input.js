// The page body and input of the scripted pages of the browser build (tests/web/*.html, bench/web/bench.html),
// served beside them: the app's canvas (1280 x 800, as index.html's) and its message line, mouse events
// dispatched on the canvas, which emscripten's GLFW takes as a user's, and the app's Module for a page whose
// script runs once the app draws its first frame.
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

// Move there, press, release, starting `at` ms from now: one frame apart at least.
function click(x, y, at) {
  setTimeout(function () { mouse('mousemove', x, y); }, at);
  setTimeout(function () { mouse('mousedown', x, y); }, at + 100);
  setTimeout(function () { mouse('mouseup', x, y); }, at + 200);
}

// The emscripten Module of a scripted page: the app's output on the console, `script` run once, at the app's
// first frame (the page's input is only read once the app runs).
function scriptedModule(script) {
  var started = false;
  return {
    canvas: canvas,
    print: function (t) { console.log(t); },
    printErr: function (t) { console.error(t); },
    fvFrame: function () {
      if (started) return;
      started = true;
      script();
    }
  };
}
