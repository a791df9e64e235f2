package io.concord.bench.concord;

import io.concord.testkit.EchoAgent;

/** A Concord echo for the HTTP benchmark: the request's content back, unchanged. */
public final class ConcordHttpEcho extends EchoAgent {
    public ConcordHttpEcho() {
        super("", m -> { });
    }
}
