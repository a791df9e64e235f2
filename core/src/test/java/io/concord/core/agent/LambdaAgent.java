package io.concord.core.agent;

import java.util.function.Consumer;

/** An agent whose setup is a lambda, for tests. */
public final class LambdaAgent extends Agent {
    private final Consumer<Agent> setup;
    public boolean tookDown;

    public LambdaAgent(Consumer<Agent> setup) {
        this.setup = setup;
    }

    @Override
    protected void setup() {
        setup.accept(this);
    }

    @Override
    protected void takeDown() {
        tookDown = true;
    }
}
