/**
 * The benchmarks' command line, report and the platforms they compare. A benchmark measures real
 * time: here the wall clock ({@code System.nanoTime}, the report's date) is read directly, not
 * through {@link io.concord.core.time.Clock}, which only the platform under test reads.
 */
package io.concord.bench;
