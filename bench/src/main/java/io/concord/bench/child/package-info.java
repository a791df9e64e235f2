/**
 * The mains of the benchmarks' child processes. What they time or wait for is real time: the wall
 * clock ({@code System.nanoTime}) is read directly here, not through
 * {@link io.concord.core.time.Clock}, which only the platform under test reads.
 */
package io.concord.bench.child;
