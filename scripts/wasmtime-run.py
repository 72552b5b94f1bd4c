"""Runs a wasm32-wasip1 program under the PyPI `wasmtime` module, for the determinism
matrix when Node is missing: python3 scripts/wasmtime-run.py PROGRAM.wasm [ARGS...]
The current directory is the only one the program sees (as `.`). Exits with the program's
exit code; a trap (a Rust panic aborts) exits 101."""
import sys

from wasmtime import Engine, ExitTrap, Linker, Module, Store, Trap, WasiConfig, WasmtimeError


def main() -> int:
    if len(sys.argv) < 2:
        print("usage: wasmtime-run.py PROGRAM.wasm [ARGS...]", file=sys.stderr)
        return 2
    program, args = sys.argv[1], sys.argv[2:]
    engine = Engine()
    linker = Linker(engine)
    linker.define_wasi()
    store = Store(engine)
    config = WasiConfig()
    config.argv = [program, *args]
    config.inherit_stdout()
    config.inherit_stderr()
    config.preopen_dir(".", ".")
    store.set_wasi(config)
    instance = linker.instantiate(store, Module.from_file(engine, program))
    try:
        instance.exports(store)["_start"](store)
    except ExitTrap as exit_trap:
        return exit_trap.code
    except (Trap, WasmtimeError) as error:
        print(f"wasmtime-run: trap: {error}", file=sys.stderr)
        return 101
    return 0


sys.exit(main())
