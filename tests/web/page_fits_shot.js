// Injected into a copy of the site's index.html by tests/web/page_fits.sh: after the 90th frame, the canvas as
// the app drew it (toDataURL in the same task as the frame, before the browser may clear the drawing buffer)
// into the body's data-fv-shot, which chromium --dump-dom writes out; page_fits.sh saves it as a PNG. A
// --screenshot would not do: headless Chromium resizes the page to its window for the shot with no frame in
// between (tests/web/screenshot.sh).
(function () {
  var frames = 0;
  Module.fvFrame = function () {
    if (++frames === 90) document.body.setAttribute('data-fv-shot', Module.canvas.toDataURL('image/png'));
  };
})();
