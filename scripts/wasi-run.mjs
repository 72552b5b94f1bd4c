// Runs a wasm32-wasip1 program under Node's built-in WASI (Node >= 20), for the
// determinism matrix: node scripts/wasi-run.mjs PROGRAM.wasm [ARGS...]
// The current directory is the only one the program sees (as `.`), so pass relative paths.
// Exits with the program's exit code; a trap (a Rust panic aborts) exits 101.
import { readFile } from 'node:fs/promises';
import process from 'node:process';
import { WASI } from 'node:wasi';

const [, , program, ...args] = process.argv;
if (!program) {
  console.error('usage: node wasi-run.mjs PROGRAM.wasm [ARGS...]');
  process.exit(2);
}
const wasi = new WASI({
  version: 'preview1',
  args: [program, ...args],
  env: {},
  preopens: { '.': process.cwd() },
  returnOnExit: true,
});
const module = await WebAssembly.compile(await readFile(program));
const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
let code;
try {
  code = wasi.start(instance);
} catch (error) {
  console.error(`wasi-run: trap: ${error?.message}`);
  code = 101;
}
process.exit(code ?? 0);
