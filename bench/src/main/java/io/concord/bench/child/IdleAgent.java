package io.concord.bench.child;

import io.concord.core.agent.Agent;

/** An agent that does nothing but take part in the platform: for the platform harnesses. */
public class IdleAgent extends Agent {
}
