// Steps per second of built-in scenes in headless Chromium (the wasm package, with and
// without simd128), and the page's load to first frame. Called by scripts/web-bench.sh,
// which serves the repository on BASE.
// Usage: node --experimental-websocket scripts/web-bench.mjs CHROMIUM BASE NAME:TICKS,...
// Prints `steps NAME KERNELS TICKS MS` (TICKS ticks from tick 0, in MS milliseconds) and
// `first-frame MS` (the median of five warm loads of the pyramid page).
import { launch } from './cdp.mjs';

const [chromium, base, scenesArg] = process.argv.slice(2);
const { page, evaluate, until, errors, close } = await launch(chromium);
const open = async (query) => {
  await page('Page.navigate', { url: 'about:blank' });
  await until("location.href === 'about:blank'", 60, 'a blank page');
  await page('Page.navigate', { url: `${base}/web/index.html?${query}` });
  await until("document.body?.dataset.firstFrame !== undefined", 60, `the page (${query})`);
};

await open('scene=tiny&ticks=1');
for (const [name, ticks] of scenesArg.split(',').map((s) => s.split(':'))) {
  for (const [kernels, path] of [['simd128', '/web/pkg/'], ['scalar', '/web/pkg/scalar/']]) {
    const ms = await evaluate(`(async () => {
      let pkg;
      try { pkg = await import('${path}fixstep_web.js'); } catch { return null; }
      await pkg.default();
      const session = pkg.Session.builtin('${name}');
      const started = performance.now();
      session.step(${ticks});
      const ms = performance.now() - started;
      session.free();
      return ms;
    })()`);
    if (ms !== null) console.log(`steps ${name} ${kernels} ${ticks} ${ms.toFixed(1)}`);
  }
}
const frames = [];
for (let i = 0; i < 6; i++) {
  await open('scene=pyramid');
  if (i > 0) frames.push(Number(await evaluate('document.body.dataset.firstFrame')));
}
frames.sort((a, b) => a - b);
console.log(`first-frame ${frames[2]}`);
for (const error of errors) console.log(`console error: ${error}`);
close();
