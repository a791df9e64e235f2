/**
 * The harnesses that start platforms, processes and boards and time them. They measure and wait
 * in real time: the wall clock ({@code System.nanoTime}) is read directly here, not through
 * {@link io.concord.core.time.Clock}, which only the platform under test reads.
 */
package io.concord.bench.harness;
