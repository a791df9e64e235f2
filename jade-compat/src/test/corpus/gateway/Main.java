import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.core.behaviours.OneShotBehaviour;
import jade.wrapper.gateway.JadeGateway;

/**
 * Non-agent code reaching the platform through JadeGateway, as a servlet would: a behaviour
 * handed over runs in the gateway agent, the caller waits until it is done; a command the
 * default gateway agent does not know times out.
 */
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
        Runtime.instance().createMainContainer(p);
        Runtime.instance().setCloseVM(false);

        jade.util.leap.Properties gw = new jade.util.leap.Properties();
        gw.setProperty(Profile.MAIN_HOST, "127.0.0.1");
        gw.setProperty(Profile.MAIN_PORT, args[0]);
        gw.setProperty(Profile.LOCAL_HOST, "127.0.0.1");
        gw.setProperty(Profile.NO_MTP, "true");
        JadeGateway.init(null, gw);
        System.out.println("active before: " + JadeGateway.isGatewayActive());
        String[] seen = new String[1];
        JadeGateway.execute(new OneShotBehaviour() {
            @Override
            public void action() {
                seen[0] = myAgent.getLocalName() + " (" + myAgent.getClass().getName() + ")";
                System.out.println("the command runs in " + seen[0]);
            }
        });
        System.out.println("executed: " + seen[0] + ", active " + JadeGateway.isGatewayActive() + ", main host "
                + JadeGateway.getProfileProperty(Profile.MAIN_HOST, "?"));
        try {
            JadeGateway.execute("not a behaviour", 1000);
            System.out.println("the string was released");
        } catch (InterruptedException e) {
            System.out.println("the string: " + e.getMessage());
        }
        JadeGateway.shutdown();
        System.out.println("active after shutdown: " + JadeGateway.isGatewayActive());
        System.exit(0);
    }
}
