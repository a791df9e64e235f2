import jade.core.AID;
import jade.core.Agent;
import jade.core.ServiceException;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.messaging.TopicManagementHelper;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Registers for the topic "news" and tells the writer each news item it reads. */
public class Reader extends Agent {
    @Override
    protected void setup() {
        try {
            TopicManagementHelper topics = (TopicManagementHelper) getHelper(TopicManagementHelper.SERVICE_NAME);
            AID news = topics.createTopic("news");
            topics.register(news);
            ACLMessage ready = new ACLMessage(ACLMessage.INFORM);
            ready.addReceiver(new AID("writer", AID.ISLOCALNAME));
            ready.setContent("ready");
            send(ready);
            MessageTemplate onNews = MessageTemplate.MatchTopic(news);
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    ACLMessage m = myAgent.receive(onNews);
                    if (m == null) {
                        block();
                        return;
                    }
                    ACLMessage seen = new ACLMessage(ACLMessage.CONFIRM);
                    seen.addReceiver(m.getSender());
                    seen.setContent(myAgent.getLocalName() + " read " + m.getContent());
                    myAgent.send(seen);
                }
            });
        } catch (ServiceException e) {
            System.out.println(getLocalName() + ": no topics: " + e.getMessage());
        }
    }
}
