package jade.wrapper.gateway;

import jade.core.Agent;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.wrapper.AgentController;
import jade.wrapper.ContainerController;
import jade.wrapper.ControllerException;
import jade.wrapper.StaleProxyException;

import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * JADE's gateway from non-agent code (a servlet, a GUI) into the platform: {@link #init} says
 * which {@link GatewayAgent} to run and with which profile; the first {@link #execute} (or
 * {@link #checkJADE}) starts a container of its own and that agent, named {@code Control} and the
 * container's name, as JADE names it; {@code execute(command)} hands the command to the agent
 * and waits until the agent releases it (or the timeout passes: {@link InterruptedException}
 * {@code "Timeout expired"}). {@link #shutdown} kills the agent and its container. Gateway
 * listeners and {@code DynamicJadeGateway} are not supported.
 */
public class JadeGateway {
    private static String agentClassName = GatewayAgent.class.getName();
    private static Object[] agentArguments;
    private static jade.util.leap.Properties profile = new jade.util.leap.Properties();
    private static ContainerController container;
    private static AgentController agent;
    private static final Map<Object, CountDownLatch> PENDING = new IdentityHashMap<>();

    JadeGateway() {
    }

    /** A property of the gateway's profile, or the default. */
    public static final String getProfileProperty(String key, String defaultValue) {
        return profile.getProperty(key, defaultValue);
    }

    /** As {@link #execute(Object, long)} with no time limit. */
    public static final void execute(Object command) throws StaleProxyException, ControllerException, InterruptedException {
        execute(command, 0);
    }

    /** Hands the command to the gateway agent (started if need be) and waits until it is released, at most {@code timeout} ms (0: no limit). */
    public static final void execute(Object command, long timeout) throws StaleProxyException, ControllerException, InterruptedException {
        checkJADE();
        CountDownLatch done = new CountDownLatch(1);
        synchronized (PENDING) {
            PENDING.put(command, done);
        }
        AgentController a;
        synchronized (JadeGateway.class) {
            a = agent;
        }
        try {
            a.putO2AObject(command, AgentController.ASYNC);
            boolean released = timeout > 0 ? done.await(timeout, TimeUnit.MILLISECONDS) : awaitForever(done);
            if (!released) {
                throw new InterruptedException("Timeout expired");
            }
        } finally {
            synchronized (PENDING) {
                PENDING.remove(command);
            }
        }
    }

    private static boolean awaitForever(CountDownLatch l) throws InterruptedException {
        l.await();
        return true;
    }

    /** The gateway agent released a command. */
    static void released(Object command) {
        synchronized (PENDING) {
            CountDownLatch l = PENDING.get(command);
            if (l != null) {
                l.countDown();
            }
        }
    }

    /** Starts the gateway's container and agent unless they run. */
    public static final synchronized void checkJADE() throws StaleProxyException, ControllerException {
        if (agent != null) {
            return;
        }
        Profile p = new ProfileImpl(profile);
        container = jade.core.Runtime.instance().createAgentContainer(p);
        Agent a;
        try {
            ClassLoader cl = Thread.currentThread().getContextClassLoader();
            Class<?> type = Class.forName(agentClassName, true, cl != null ? cl : JadeGateway.class.getClassLoader());
            a = (Agent) type.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | ClassCastException | LinkageError e) {
            throw new StaleProxyException("cannot create the gateway agent of class " + agentClassName + ": " + e);
        }
        a.setArguments(agentArguments);
        AgentController c = container.acceptNewAgent("Control" + container.getContainerName(), a);
        c.start();
        agent = c;
    }

    /** The gateway agent's class (null: {@link GatewayAgent}), its arguments, and the profile of its container. */
    public static final synchronized void init(String agentClassName, Object[] agentArgs, jade.util.leap.Properties jadeProfile) {
        JadeGateway.agentClassName = agentClassName == null ? GatewayAgent.class.getName() : agentClassName;
        JadeGateway.agentArguments = agentArgs;
        JadeGateway.profile = jadeProfile == null ? new jade.util.leap.Properties() : jadeProfile;
    }

    public static final void init(String agentClassName, jade.util.leap.Properties jadeProfile) {
        init(agentClassName, null, jadeProfile);
    }

    /** Kills the gateway agent and its container. */
    public static final synchronized void shutdown() {
        try {
            if (container != null) {
                container.kill();
            }
        } catch (StaleProxyException e) {
            // already gone: nothing more to stop
            agent = null;
        } finally {
            agent = null;
            container = null;
        }
    }

    /** True while the gateway agent runs. */
    public static final synchronized boolean isGatewayActive() {
        return agent != null;
    }
}
