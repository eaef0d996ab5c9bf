/** The relative run-time imports of a module (type-only imports left out), as module paths. */
export function importsOf(file: string, text: string): string[];
/** Every cycle a depth-first search meets, each as its modules with the first repeated last. */
export function cycles(graph: Map<string, string[]>): string[][];
