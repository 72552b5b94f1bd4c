// The live page in headless Chromium, driven over the DevTools protocol (scripts/cdp.mjs;
// run with `node --experimental-websocket` on Node 20). Called by
// scripts/web-test.sh, which serves the repository on BASE and checks what this prints.
// Usage: node --experimental-websocket scripts/web-test.mjs CHROMIUM BASE OUT SCENES REPLAYS
//   [LIVE_PAGE]
//   SCENES: NAME:TICKS,...  REPLAYS: file names in replays/, comma-separated
//   LIVE_PAGE: a page written by `fixstep render REPLAY --html`, opened from file://
// Prints one line per check: `checksum NAME TICKS HEX`, `drawn NAME CHARACTERS WATER_VERTICES`,
// `live-page TICK HEX VERDICT`, `replay FILE VERDICT MS LINE`,
// `bad-replay VERDICT MESSAGE`, `recorded PATH COMMANDS`, `first-frame MS`, `screenshot
// PATH SHARE`, then `console-errors N` (and each error); exits 1 on a failure it can see.
import { readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { inflateSync } from 'node:zlib';
import { launch, sleep } from './cdp.mjs';

const [chromium, base, out, scenesArg, replaysArg, livePage] = process.argv.slice(2);
const scenes = scenesArg.split(',').map((s) => s.split(':'));
const replays = replaysArg ? replaysArg.split(',') : [];
const downloads = join(out, 'downloads');
const { page, evaluate, until, errors, close } = await launch(chromium, downloads);
const open = async (query) => {
  await page('Page.navigate', { url: `${base}/web/index.html?${query}` });
  await until("document.readyState === 'complete' && window.fixstepPage?.session != null", 60, `the page (${query})`);
};
let failed = false;
const fail = (line) => { console.log(`FAIL ${line}`); failed = true; };

try {
  // The checksum after N ticks, and the time to the first frame.
  for (const [name, ticks] of scenes) {
    await open(`scene=${name}&ticks=${ticks}`);
    await until("document.body.dataset.done === '1'", 300, `${name} to reach tick ${ticks}`);
    console.log(`checksum ${name} ${ticks} ${await evaluate("document.getElementById('checksum').textContent")}`);
    if (name === scenes[0][0]) {
      console.log(`first-frame ${await evaluate('document.body.dataset.firstFrame')}`);
      const { data } = await page('Page.captureScreenshot', { format: 'png' });
      const path = join(out, `${name}.png`);
      writeFileSync(path, Buffer.from(data, 'base64'));
      const share = colouredShare(Buffer.from(data, 'base64'));
      console.log(`screenshot ${path} ${share.toFixed(4)}`);
      if (share < 0.005) fail('the canvas is blank (under 0.5 % of it in colour)');
    }
  }

  // Characters and water drawn as meshes that follow the world.
  // (pond's first drop falls at tick 30.)
  for (const name of ['parkour', 'pond']) {
    await open(`scene=${name}&ticks=40`);
    await until("document.body.dataset.done === '1'", 120, `${name} to reach tick 40`);
    const [characters, water, moved] = await evaluate(`(() => {
      const { view, session } = window.fixstepPage;
      const water = view.water?.geometry.getAttribute('position');
      const centres = Array.from(session.characterPositions());
      let moved = view.characters.length > 0 && view.characters.every((c, i) =>
        c.position.toArray().every((x, k) => Math.abs(x - centres[3 * i + k]) < 1e-6));
      if (water) {
        const heights = session.waterHeights();
        const level = view.water.userData.restLevel;
        moved = heights.some((h) => h !== 0)
          && heights.every((h, i) => Math.abs(water.getY(i) - (level + h)) < 1e-6);
      }
      return [view.characters.length, water?.count ?? 0, moved];
    })()`);
    console.log(`drawn ${name} ${characters} ${water} ${moved}`);
    if (!moved || (name === 'parkour' ? characters !== 3 : water === 0)) {
      fail(`${name}: its characters or its water are not drawn where the world has them`);
    }
  }

  // A page written by `fixstep render REPLAY --html`, opened as a file.
  if (livePage) {
    await page('Page.navigate', { url: `file://${livePage}` });
    await until("document.body?.dataset.done === '1'", 120, 'the written live page to play its replay');
    const [tick, checksum, verdict] = await evaluate(`[document.body.dataset.tick,
      document.getElementById('checksum').textContent, document.getElementById('status').dataset.verdict]`);
    console.log(`live-page ${tick} ${checksum} ${verdict}`);
    if (verdict !== 'ok') fail('the written live page did not end at the recorded checksum');
  }

  // Every replay dropped on the page, then bad bytes.
  await open('scene=stack&ticks=1');
  const drop = (name, cut) => evaluate(`(async () => {
    const bytes = new Uint8Array(await (await fetch('/replays/${name}')).arrayBuffer());
    const data = new DataTransfer();
    data.items.add(new File([${cut} ? bytes.slice(0, bytes.length >> 1) : bytes], '${name}'));
    const started = performance.now();
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: data, cancelable: true }));
    await window.fixstepPage.verifying;
    const status = document.getElementById('status');
    return [status.dataset.verdict, Math.round(performance.now() - started), status.textContent];
  })()`);
  for (const name of replays) {
    const [verdict, ms, text] = await drop(name, false);
    console.log(`replay ${name} ${verdict} ${ms} ${text.replace(/\s+/g, ' ')}`);
    if (verdict !== 'ok') fail(`${name} did not verify in the browser`);
  }
  const [verdict, , text] = await drop('stack.replay', true);
  console.log(`bad-replay ${verdict} ${text}`);
  if (verdict !== 'error' || !/section/.test(text) || !/offset/.test(text)) {
    fail('bad replay bytes did not give an error naming the section and offset');
  }

  // Clicks on two boxes of the stack, then the replay downloaded.
  await open('scene=stack');
  await until('window.fixstepPage.session.tick > 20', 60, 'the stack to run');
  for (const pick of [0.4, 0.8]) {
    const [x, y] = await evaluate(`(() => {
      const bodies = window.fixstepPage.view.bodies.filter((b) => b.userData.dynamic);
      return window.fixstepPage.screenPoint(bodies[Math.floor(bodies.length * ${pick})].userData.body);
    })()`);
    for (const type of ['mouseMoved', 'mousePressed', 'mouseReleased']) {
      await page('Input.dispatchMouseEvent', { type, x, y, button: 'left', clickCount: 1 });
    }
    await sleep(200);
  }
  await until('window.fixstepPage.session.commandTicks >= 2', 20, 'two pushes to be applied');
  const commands = await evaluate('window.fixstepPage.session.commandTicks');
  await evaluate("document.getElementById('download').click()");
  let file;
  for (const end = Date.now() + 30000; !file && Date.now() < end; await sleep(100)) {
    try {
      file = readdirSync(downloads).find((f) => f.endsWith('.replay'));
    } catch { /* not there yet */ }
  }
  if (!file) fail('no replay was downloaded');
  else console.log(`recorded ${join(downloads, file)} ${commands}`);
} catch (error) {
  fail(error.message);
}
console.log(`console-errors ${errors.length}`);
for (const error of errors) console.log(`  ${error}`);
if (errors.length) failed = true;
close();
process.exit(failed ? 1 : 0);

// The share of a PNG's pixels in saturated colour (the background and ground are grey).
function colouredShare(png) {
  let pos = 8;
  let idat = Buffer.alloc(0);
  let width, height, channels;
  while (pos < png.length) {
    const length = png.readUInt32BE(pos);
    const kind = png.toString('latin1', pos + 4, pos + 8);
    const body = png.subarray(pos + 8, pos + 8 + length);
    if (kind === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      channels = body[9] === 6 ? 4 : 3;
    } else if (kind === 'IDAT') {
      idat = Buffer.concat([idat, body]);
    }
    pos += 12 + length;
  }
  const raw = inflateSync(idat);
  const stride = width * channels;
  let previous = new Uint8Array(stride);
  let coloured = 0;
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const row = Uint8Array.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; i++) {
      const a = i >= channels ? row[i - channels] : 0;
      const b = previous[i];
      const c = i >= channels ? previous[i - channels] : 0;
      const p = a + b - c;
      const paeth = Math.abs(p - a) <= Math.abs(p - b) && Math.abs(p - a) <= Math.abs(p - c)
        ? a : Math.abs(p - b) <= Math.abs(p - c) ? b : c;
      row[i] = (row[i] + [0, a, b, (a + b) >> 1, paeth][filter]) & 255;
    }
    for (let x = 0; x < stride; x += channels) {
      if (Math.max(row[x], row[x + 1], row[x + 2]) - Math.min(row[x], row[x + 1], row[x + 2]) > 40) coloured++;
    }
    previous = row;
  }
  return coloured / (width * height);
}
