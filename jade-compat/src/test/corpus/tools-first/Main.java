import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.wrapper.AgentContainer;
import jade.wrapper.AgentController;

/** A launcher that starts JADE's tool agents (the RMA, the Sniffer, ...) before its own agents, as many JADE projects do. */
public class Main {
    public static void main(String[] args) throws Exception {
        Profile p = new ProfileImpl();
        p.setParameter(Profile.MAIN_HOST, "127.0.0.1");
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.MAIN_PORT, args[0]);
        p.setParameter(Profile.LOCAL_PORT, args[0]);
        p.setParameter(Profile.PLATFORM_ID, "corpus");
        p.setParameter(Profile.GUI, "false");
        p.setParameter(Profile.NO_MTP, "true");
        p.setParameter(Profile.DETECT_MAIN, "false");
        AgentContainer c = Runtime.instance().createMainContainer(p);
        c.createNewAgent("rma", "jade.tools.rma.rma", null).start();
        c.createNewAgent("sniffer", "jade.tools.sniffer.Sniffer", null).start();
        c.createNewAgent("dummy", "jade.tools.DummyAgent.DummyAgent", null).start();
        c.createNewAgent("listener", "Listener", null).start();
        c.createNewAgent("greeter", "Greeter", new Object[] {"listener"}).start();
    }
}
