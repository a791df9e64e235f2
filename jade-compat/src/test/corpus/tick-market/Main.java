import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.wrapper.AgentContainer;
import jade.wrapper.AgentController;

/** Starts the platform from code, as JADE's tutorials do, on the port given, loopback only. */
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
        c.createNewAgent("s1", "Trader", new Object[] {"12"}).start();
        c.createNewAgent("s2", "Trader", new Object[] {"9"}).start();
        c.createNewAgent("s3", "Trader", new Object[] {"15"}).start();
        c.createNewAgent("market", "Market", null).start();
    }
}
