// Runs a wasm32-wasip1 program under Node's built-in WASI (Node >= 20), for the
// determinism matrix, the cross-target unit tests and the peer bench:
//   node scripts/wasi-run.mjs PROGRAM.wasm [ARGS...]
// The current directory is the only one the program sees (as `.`), so pass relative paths.
// Of the environment it sees only FIXSTEP_SIMD (the cap on the engine's kernels), when set.
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
  env: process.env.FIXSTEP_SIMD === undefined ? {} : { FIXSTEP_SIMD: process.env.FIXSTEP_SIMD },
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
