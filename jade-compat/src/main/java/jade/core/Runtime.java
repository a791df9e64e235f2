package jade.core;

import io.concord.jadecompat.internal.Engine;
import jade.wrapper.AgentContainer;

import java.util.ArrayList;
import java.util.List;

/**
 * JADE's entry point for starting agents from code: {@code Runtime.instance().createMainContainer(p)}.
 * Here there is no main container: the first container of the JVM starts a Concord platform
 * (named {@code Profile.PLATFORM_ID}, default {@code <host>:<port>/JADE} as JADE names it), and
 * every container of the JVM puts its agents on it.
 */
public class Runtime {
    private static final Runtime INSTANCE = new Runtime();

    private final List<Runnable> terminators = new ArrayList<>();
    private boolean closeVm;

    private Runtime() {
    }

    public static Runtime instance() {
        return INSTANCE;
    }

    /** A main container: here, a container on this JVM's Concord platform. */
    public AgentContainer createMainContainer(Profile p) {
        return create(p, "Main-Container");
    }

    /** A peripheral container: here, also a container on this JVM's Concord platform. */
    public AgentContainer createAgentContainer(Profile p) {
        return create(p, null);
    }

    private synchronized AgentContainer create(Profile p, String defaultName) {
        String host = p.getParameter(Profile.LOCAL_HOST, p.getParameter(Profile.MAIN_HOST, "127.0.0.1"));
        if (Profile.LOCALHOST_CONSTANT.equals(host)) {
            host = Profile.LOOPBACK_ADDRESS_CONSTANT;
        }
        String portText = p.getParameter(Profile.LOCAL_PORT, p.getParameter(Profile.MAIN_PORT, null));
        int port = portText == null ? 0 : Integer.parseInt(portText.trim());
        String platformName = p.getParameter(Profile.PLATFORM_ID,
                host + ":" + (port > 0 ? port : Profile.DEFAULT_PORT) + "/JADE");
        boolean gui = "true".equalsIgnoreCase(p.getParameter(Profile.GUI, "false").trim());
        Engine e = Engine.start(platformName, host, port, gui);
        AID.platformId = e.platformName();
        String name = p.getParameter(Profile.CONTAINER_NAME, defaultName);
        return new AgentContainer(e, name == null ? "Container-" + nextContainer() : name);
    }

    private int containers;

    private int nextContainer() {
        return ++containers;
    }

    /** Whether the JVM exits when the last container is killed. */
    public void setCloseVM(boolean closeVM) {
        this.closeVm = closeVM;
    }

    /** Starting a platform from a profile alone: use createMainContainer. */
    public void startUp(Profile p) {
        createMainContainer(p);
    }

    /** Stops the platform and runs the terminators. */
    public void shutDown() {
        Engine.shutDown();
        List<Runnable> ts;
        synchronized (this) {
            ts = new ArrayList<>(terminators);
        }
        for (Runnable r : ts) {
            r.run();
        }
        if (closeVm) {
            System.exit(0);
        }
    }

    /** Runs {@code r} when the platform shuts down. */
    public synchronized void invokeOnTermination(Runnable r) {
        terminators.add(r);
    }

    public synchronized void resetTerminators() {
        terminators.clear();
    }

    public static String getCopyrightNotice() {
        return "concord-jade: JADE's API over Concord (not JADE; JADE is (c) Telecom Italia, LGPL)";
    }

    public static String getVersionInfo() {
        return "concord-jade " + getVersion();
    }

    public static String getVersion() {
        return "4.3";
    }

    public static String getRevision() {
        return "concord";
    }

    public static String getDate() {
        return "";
    }
}
