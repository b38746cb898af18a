// Runs the built bench CLI's `main(argv, io)` once for each argument list of the JSON array in the
// environment variable BENCH_ARGVS, one after another in this process, and writes a JSON array to stdout:
// per run, its return value (the exit code the CLI exits with) as `code`, and its `stdout` and `stderr`:
// what the CLI writes through `io` and whatever else the run writes to the process's streams (a peer
// engine's console.log on this thread, say), as a process of its own would show them. A run that throws
// instead of returning gives code -1 and the error. BENCH_CLI is the file URL of the built CLI.
// A file, not `node -e`: worker threads (the isolated peers) never start under `--input-type=module -e`.
const { main } = await import(process.env.BENCH_CLI);
const write = { out: process.stdout.write, err: process.stderr.write };
const runs = [];
for (const argv of JSON.parse(process.env.BENCH_ARGVS)) {
  let stdout = '';
  let stderr = '';
  process.stdout.write = (text) => {
    stdout += String(text);
    return true;
  };
  process.stderr.write = (text) => {
    stderr += String(text);
    return true;
  };
  const io = {
    out: (text) => {
      stdout += `${text}\n`;
    },
    err: (text) => {
      stderr += `${text}\n`;
    },
    isTTY: false,
  };
  try {
    runs.push({ code: await main(argv, io), stdout, stderr });
  } catch (error) {
    runs.push({ code: -1, stdout, stderr: stderr + String(error?.stack) });
  }
}
process.stdout.write = write.out;
process.stderr.write = write.err;
// Exits once written: peers' WebAssembly compiling in the background could keep the process on.
process.stdout.write(JSON.stringify(runs), () => process.exit(0));
