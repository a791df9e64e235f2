/**
 * The JADE side of the benchmarks: JADE's agents and platform, written as a JADE user writes them,
 * so they read the wall clock ({@code System.currentTimeMillis}) as JADE's own agents do.
 */
package io.concord.bench.jade;
