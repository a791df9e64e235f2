package io.concord.bench.support;

/** What the links of the chain benchmarks (Concord's and JADE's, in one JVM or many) pass on. */
public final class Chain {
    /** The 500-byte content each link checks, as in the dissertation's chain test. */
    public static final String SECRET = "s".repeat(492) + "checksum";

    private Chain() {
    }
}
