package jade.core;

/** Where an agent can be: a container. */
public interface Location extends jade.util.leap.Serializable, jade.content.Concept {
    String getID();

    String getName();

    String getProtocol();

    String getAddress();
}
