package io.concord.dist;

import jade.core.Agent;

/** A JADE agent as JADE's tutorials write one, started by {@code jade.Boot} from the runnable jar: it greets and ends the JVM. */
public class JadeCompatAgent extends Agent {
    @Override
    protected void setup() {
        System.out.println("jade agent " + getName() + " with " + getArguments().length + " arguments");
        System.exit(0);
    }
}
