package jade.tools.DummyAgent;

import io.concord.jadecompat.internal.ToolStandIn;

/**
 * A stand-in for JADE's Dummy Agent (jade.tools.DummyAgent.DummyAgent): started under JADE's class name (from {@code jade.Boot -agents}
 * or {@code createNewAgent}), it says once on standard error what Concord offers instead (its web
 * console) and ends, so that the launcher goes on.
 */
public class DummyAgent extends jade.core.Agent {
    private static final long serialVersionUID = 1L;

    public DummyAgent() {
        super();
    }

    @Override
    protected void setup() {
        ToolStandIn.standIn(this, "JADE's Dummy Agent (jade.tools.DummyAgent.DummyAgent)");
    }
}
