// Peer benchmark: Rabbit Ear's layer solver (npm rabbit-ear, a dev dependency of the benchmark
// only; orikin never links it). For each FOLD file given: fold the crease pattern flat with
// Rabbit Ear, run its global layer solver, and print one JSON line
//   {"file", "faces", "setup_ms", "solve_ms", "states", "error"}
// where setup_ms is folding plus graph preparation, solve_ms the solver (its own constraint
// building included, as Rabbit Ear does both in one call), states the product of its branch
// counts. Run from the repository root: node bench/peers/rabbit_ear_layers.mjs FILE...
import fs from "fs";
import { performance } from "perf_hooks";
import ear from "rabbit-ear";

const quiet = console.log;
for (const file of process.argv.slice(2)) {
	const out = { file };
	try {
		const fold = JSON.parse(fs.readFileSync(file, "utf-8"));
		const folded = (fold.frame_classes || []).includes("foldedForm");
		const t0 = performance.now();
		const graph = JSON.parse(JSON.stringify(fold));
		if (!graph.edges_assignment) graph.edges_assignment = graph.edges_vertices.map(() => "U");
		ear.graph.populate(graph);
		if (!folded) graph.vertices_coords = ear.graph.makeVerticesCoordsFlatFolded(graph, 0);
		const t1 = performance.now();
		console.log = () => {}; // the solver logs its own timings
		const solution = ear.layer.solver(graph);
		console.log = quiet;
		const t2 = performance.now();
		out.faces = graph.faces_vertices.length;
		out.setup_ms = t1 - t0;
		out.solve_ms = t2 - t1;
		out.states = solution ? solution.count().reduce((a, b) => a * BigInt(b), 1n).toString() : "0";
	} catch (e) {
		console.log = quiet;
		out.error = String(e && e.message ? e.message : e).slice(0, 160);
	}
	console.log(JSON.stringify(out));
}
