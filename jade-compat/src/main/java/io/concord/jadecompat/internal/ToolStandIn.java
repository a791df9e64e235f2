package io.concord.jadecompat.internal;

/**
 * What JADE's tool agents (the RMA, the Sniffer, the Dummy Agent, the Introspector) do here: they
 * are JADE's Swing windows, which concord-jade does not have. Each stand-in, started under
 * JADE's class name, says once on standard error what Concord offers instead and ends itself, so
 * that a launcher that starts one goes on with its own agents (as on JADE without a display,
 * where the tool fails in its own setup and the rest runs).
 */
public final class ToolStandIn {
    private ToolStandIn() {
    }

    /** The line a stand-in prints for JADE's {@code tool}, started as {@code agentName}. */
    public static String notice(String agentName, String tool) {
        return "concord-jade: " + agentName + " is " + tool + ", a JADE window that concord-jade does not have; it ends now and "
                + "the platform goes on. Concord's web console shows the agents, their messages and the DF instead: "
                + "jade.Boot -gui (or Profile.GUI true) opens it when concord-console is on the class path, "
                + "as does Concord's own -console [host:]port.";
    }

    /** Says so on standard error and deletes the agent. */
    public static void standIn(jade.core.Agent a, String tool) {
        System.err.println(notice(a.getLocalName(), tool));
        a.doDelete();
    }
}
