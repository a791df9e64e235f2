package jade.core.messaging;

import jade.core.AID;

/** Topic AIDs: {@code name@TOPIC_}, as JADE makes them. */
public class TopicUtility {
    public TopicUtility() {
    }

    public static final AID createTopic(String topicName) {
        return new AID(topicName + "@" + TopicManagementHelper.TOPIC_SUFFIX, AID.ISGUID);
    }

    public static final boolean isTopic(AID id) {
        return id != null && id.getName() != null && id.getName().endsWith("@" + TopicManagementHelper.TOPIC_SUFFIX);
    }
}
