package jade.wrapper;

/** JADE's platform event (an agent born or dead, the platform started, ...), as a {@link PlatformController.Listener} would get it. */
public interface PlatformEvent {
    int BORN_AGENT = 3;
    int DEAD_AGENT = 4;
    int STARTED_PLATFORM = 100;
    int SUSPENDED_PLATFORM = 101;
    int RESUMED_PLATFORM = 102;
    int KILLED_PLATFORM = 103;

    String getAgentGUID();

    String getPlatformName();

    int getEventType();
}
