import jade.gui.GuiAgent;
import jade.gui.GuiEvent;
import jade.util.leap.Iterator;

/**
 * A GuiAgent as JADE's examples write one, run without a window: its "user interface" is a plain
 * thread (what a Swing button's listener would do) that posts events; the agent handles them on
 * its own thread, in order.
 */
public class Clerk extends GuiAgent {
    static final int ORDER = 1;
    static final int EXIT = 2;
    private Thread agentThread;

    @Override
    protected void setup() {
        agentThread = Thread.currentThread();
        Thread ui = new Thread(() -> {
            GuiEvent order = new GuiEvent(this, ORDER);
            order.addParameter("Dune");
            order.addParameter(Integer.valueOf(2));
            postGuiEvent(order);
            GuiEvent second = new GuiEvent("the form", ORDER);
            second.addParameter("Emma");
            postGuiEvent(second);
            postGuiEvent(new GuiEvent(this, EXIT));
        }, "ui");
        ui.start();
        System.out.println(getLocalName() + " is up, its state: " + getAgentState());
    }

    @Override
    protected void onGuiEvent(GuiEvent ev) {
        StringBuilder params = new StringBuilder();
        for (Iterator it = ev.getAllParameter(); it.hasNext(); ) {
            params.append(' ').append(it.next());
        }
        System.out.println("event " + ev.getType() + " from " + (ev.getSource() == this ? "the agent" : ev.getSource())
                + " on the agent's thread: " + (Thread.currentThread() == agentThread) + ", parameters:" + params
                + (ev.getType() == ORDER ? ", first " + ev.getParameter(0) : ""));
        if (ev.getType() == EXIT) {
            doDelete();
        }
    }

    @Override
    protected void takeDown() {
        System.out.println(getLocalName() + " done");
        System.exit(0);
    }
}
